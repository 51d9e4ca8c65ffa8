#pragma once
// kse-match's guard against a behaviour that hangs or crashes and against Ctrl+C: whatever
// happens, the run ends with a message that says what happened (and to which robot) and a log
// that holds the match up to that moment in whole JSON lines.

#include <chrono>
#include <csignal>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <thread>

#include <kse/sim/RobotReports.h>

namespace kse::sim {

class JsonLinesLog;
class LogFile;

class MatchSupervisor {
public:
	/** The exit status when a robot hangs; a signal gives 128 + its number, a crash dies of its signal. */
	static constexpr int kHangExitStatus = 3;

	struct Options {
		/**
		 * A robot whose behaviour has been in one call for this long (the engine's watchdog reports
		 * it first, after its own limit) ends the match; zero: never.
		 */
		std::chrono::milliseconds hang_limit{5000};
	};

	/**
	 * Make it before the Match: it blocks SIGINT, SIGTERM and SIGHUP in this thread, so in every
	 * thread started after it, and takes them on its own thread; it catches SIGSEGV, SIGBUS,
	 * SIGFPE, SIGILL and SIGABRT. Every second it writes the log file out. {@code file} and
	 * {@code log} may be null (no log).
	 */
	MatchSupervisor(Options options, LogFile* file, JsonLinesLog* log);
	~MatchSupervisor();
	MatchSupervisor(const MatchSupervisor&) = delete;
	MatchSupervisor& operator=(const MatchSupervisor&) = delete;

	/** Give it every robot's reports (Match::Reports().SetListener): an overrun starts the robot's hang clock. */
	void OnReport(const RobotReport& report);
	/**
	 * Also told when the match ends for a hang or a signal (reason "hang" or "signal", the robot's
	 * id or "", what happened), on the supervisor's thread, after the log and before the exit: the
	 * live monitor's clients get the "aborted" record too. Not for a crash (nothing but
	 * async-signal-safe calls then).
	 */
	void OnAbort(std::function<void(const std::string& reason, const std::string& robot, const std::string& detail)> listener);
	/**
	 * A file to remove when the match ends for a hang, a signal or a crash (the match's
	 * announcement in the discovery folder, MatchDiscovery.h: a dead match must not stay listed);
	 * empty: none. One path, at most 511 bytes (it is kept where a crash handler can reach it).
	 */
	void RemoveAtExit(const std::string& path);

private:
	struct Stuck {
		std::string robot;
		std::string behaviour;
		std::string call;
		std::string chart;
		std::chrono::steady_clock::time_point since;
	};

	void Run();
	[[noreturn]] void EndForHang(const Stuck& stuck, std::chrono::steady_clock::duration running);
	[[noreturn]] void EndForSignal(int signal);
	void Abort(const std::string& reason, const std::string& robot, const std::string& detail);
	static void OnCrash(int signal);

	Options options_;
	LogFile* file_;
	JsonLinesLog* log_;
	std::mutex mutex_;
	std::map<std::uint64_t, Stuck> stuck_;  // by overrun
	std::mutex abort_mutex_;  // not mutex_: a hang is ended with mutex_ held
	std::function<void(const std::string&, const std::string&, const std::string&)> on_abort_;
	bool stopping_ = false;
	sigset_t previous_mask_;
	struct sigaction previous_crash_[5];
	std::thread thread_;
};

}  // namespace kse::sim
