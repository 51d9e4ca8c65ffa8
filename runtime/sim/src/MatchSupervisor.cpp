#include <kse/sim/MatchSupervisor.h>

#include <pthread.h>
#include <signal.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>

#include <kse/sim/LogFile.h>
#include <kse/sim/Match.h>
#include <kse/sim/MatchLog.h>

namespace kse::sim {

namespace {

constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP};
constexpr int kCrashSignals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
constexpr long kLookNanoseconds = 50'000'000;  // how soon a hang or the log's second is noticed

std::atomic<LogFile*> active_file{nullptr};
std::atomic<JsonLinesLog*> active_log{nullptr};

// The file RemoveAtExit() named, in a buffer the crash handler may read (no allocation there);
// empty: none.
char remove_at_exit[512];
std::atomic<bool> remove_set{false};

void RemoveAnnouncedFile() {
	if (remove_set.load()) ::unlink(remove_at_exit);
}

// Room for the crash handler on a stack of its own: a behaviour that recursed too deep has
// no stack left for it.
alignas(16) char crash_stack[1 << 16];

const char* SignalName(int signal) {
	switch (signal) {
		case SIGINT: return "SIGINT";
		case SIGTERM: return "SIGTERM";
		case SIGHUP: return "SIGHUP";
		case SIGSEGV: return "SIGSEGV";
		case SIGBUS: return "SIGBUS";
		case SIGFPE: return "SIGFPE";
		case SIGILL: return "SIGILL";
		case SIGABRT: return "SIGABRT";
		default: return "a signal";
	}
}

sigset_t StopSignals() {
	sigset_t set;
	sigemptyset(&set);
	for (const int signal : kStopSignals) sigaddset(&set, signal);
	return set;
}

std::string SimTime(const JsonLinesLog* log) {
	return log ? "t = " + Fixed(static_cast<double>(log->LastCentiseconds()) / 100, 2) + " s" : std::string("an unknown time");
}

// Async-signal-safe text for the crash handler.
struct Text {
	char data[1024];
	std::size_t size = 0;
	void Add(const char* text) {
		for (; *text != '\0' && size + 1 < sizeof data; ++text) data[size++] = *text;
	}
	void AddCentiseconds(std::int64_t value) {
		char digits[24];
		std::size_t count = 0;
		if (value < 0) value = 0;
		do {
			digits[count++] = static_cast<char>('0' + value % 10);
			value /= 10;
		} while (value > 0 || count < 3);
		char text[32];
		std::size_t length = 0;
		for (std::size_t i = count; i-- > 0;) {
			text[length++] = digits[i];
			if (i == 2) text[length++] = '.';
		}
		text[length] = '\0';
		Add(text);
	}
};

}  // namespace

MatchSupervisor::MatchSupervisor(Options options, LogFile* file, JsonLinesLog* log) : options_(options), file_(file), log_(log) {
	const sigset_t stop = StopSignals();
	pthread_sigmask(SIG_BLOCK, &stop, &previous_mask_);

	stack_t stack{};
	stack.ss_sp = crash_stack;
	stack.ss_size = sizeof crash_stack;
	sigaltstack(&stack, nullptr);
	struct sigaction crash {};
	crash.sa_handler = &MatchSupervisor::OnCrash;
	crash.sa_flags = static_cast<int>(SA_RESETHAND | SA_ONSTACK);  // the second fault (or the re-raise) is the default: death
	sigemptyset(&crash.sa_mask);
	for (std::size_t i = 0; i < std::size(kCrashSignals); ++i) sigaction(kCrashSignals[i], &crash, &previous_crash_[i]);

	active_file.store(file);
	active_log.store(log);
	thread_ = std::thread([this] { Run(); });
}

MatchSupervisor::~MatchSupervisor() {
	{
		std::lock_guard<std::mutex> lock(mutex_);
		stopping_ = true;
	}
	thread_.join();
	active_log.store(nullptr);
	active_file.store(nullptr);
	remove_set.store(false);
	for (std::size_t i = 0; i < std::size(kCrashSignals); ++i) sigaction(kCrashSignals[i], &previous_crash_[i], nullptr);
	pthread_sigmask(SIG_SETMASK, &previous_mask_, nullptr);
}

void MatchSupervisor::OnReport(const RobotReport& report) {
	using Kind = statechart_engine::EngineReport::Kind;
	if (report.report.kind != Kind::Overrun && report.report.kind != Kind::OverrunEnded) return;
	std::lock_guard<std::mutex> lock(mutex_);
	if (report.report.kind == Kind::OverrunEnded) {
		stuck_.erase(report.report.overrun);
	} else {
		stuck_[report.report.overrun] = {report.robot, report.behaviour, report.report.call, report.report.chart,
		                                 std::chrono::steady_clock::now() - report.report.running};
	}
}

void MatchSupervisor::Run() {
	const sigset_t stop = StopSignals();
	const timespec look{0, kLookNanoseconds};
	for (;;) {
		const int signal = sigtimedwait(&stop, nullptr, &look);
		if (signal > 0) EndForSignal(signal);
		if (file_) file_->FlushIfDue();
		std::lock_guard<std::mutex> lock(mutex_);
		if (stopping_) return;
		if (options_.hang_limit.count() <= 0) continue;
		const auto now = std::chrono::steady_clock::now();
		for (const auto& [overrun, stuck] : stuck_) {
			if (now - stuck.since >= options_.hang_limit) EndForHang(stuck, now - stuck.since);
		}
	}
}

void MatchSupervisor::OnAbort(std::function<void(const std::string&, const std::string&, const std::string&)> listener) {
	std::lock_guard lock(abort_mutex_);
	on_abort_ = std::move(listener);
}

void MatchSupervisor::RemoveAtExit(const std::string& path) {
	remove_set.store(false);
	if (path.empty() || path.size() >= sizeof remove_at_exit) return;
	std::memcpy(remove_at_exit, path.c_str(), path.size() + 1);
	remove_set.store(true);
}

void MatchSupervisor::Abort(const std::string& reason, const std::string& robot, const std::string& detail) {
	std::lock_guard lock(abort_mutex_);
	if (on_abort_) on_abort_(reason, robot, detail);
}

void MatchSupervisor::EndForHang(const Stuck& stuck, std::chrono::steady_clock::duration running) {
	const std::string seconds = Fixed(std::chrono::duration<double>(running).count(), 1);
	std::cerr << "kse-match: " << stuck.robot << " " << stuck.behaviour << " has been stuck for " << seconds << " s in the " << stuck.call
	          << " (statechart '" << stuck.chart << "'): the match cannot go on and ends at " << SimTime(log_) << " with exit status "
	          << kHangExitStatus << (file_ ? "; the log " + file_->Path() + " holds the match up to here" : std::string()) << std::endl;
	const std::string detail = stuck.behaviour + " stuck for " + seconds + " s in the " + stuck.call;
	if (log_) log_->Aborted("hang", stuck.robot, detail);
	if (file_) file_->Flush();
	RemoveAnnouncedFile();
	Abort("hang", stuck.robot, detail);
	std::fflush(nullptr);
	// Not exit(): the match's thread is still inside the behaviour, and static destructors
	// would pull its objects from under it.
	std::_Exit(kHangExitStatus);
}

void MatchSupervisor::EndForSignal(int signal) {
	std::cerr << "kse-match: interrupted (" << SignalName(signal) << ") at " << SimTime(log_)
	          << (file_ ? "; the log " + file_->Path() + " holds the match up to here" : std::string()) << std::endl;
	if (log_) log_->Aborted("signal", "", SignalName(signal));
	if (file_) file_->Flush();
	RemoveAnnouncedFile();
	Abort("signal", "", SignalName(signal));
	std::fflush(nullptr);
	std::_Exit(128 + signal);
}

// Only async-signal-safe calls from here on: the process is in an unknown state.
void MatchSupervisor::OnCrash(int signal) {
	const char* robot = Match::ThinkingRobot();
	JsonLinesLog* log = active_log.load();
	LogFile* file = active_file.load();
	Text message;
	message.Add("kse-match: crashed (");
	message.Add(SignalName(signal));
	message.Add(")");
	if (robot != nullptr) {
		message.Add(" while ");
		message.Add(robot);
		message.Add(" ran its behaviour");
	}
	if (log != nullptr) {
		message.Add(", at t = ");
		message.AddCentiseconds(log->LastCentiseconds());
		message.Add(" s");
	}
	if (file != nullptr) message.Add("; the log holds the match up to here");
	message.Add("\n");
	[[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, message.data, message.size);
	RemoveAnnouncedFile();  // unlink() is async-signal-safe
	if (file != nullptr) {
		char line[512];
		char id[64] = {};
		if (robot != nullptr) {  // "home-2 Crasher": the id is the first word
			for (std::size_t i = 0; i + 1 < sizeof id && robot[i] != '\0' && robot[i] != ' '; ++i) id[i] = robot[i];
		}
		const std::size_t length = JsonLinesLog::AbortedLine(line, sizeof line, log != nullptr ? log->LastCentiseconds() : 0, "crash",
		                                                     robot != nullptr ? id : nullptr, SignalName(signal));
		file->FlushFromSignal(line, length);
	}
	// SA_RESETHAND made the action the default again: the signal, pending until this returns,
	// kills the process as it would have (a core dump included).
	::raise(signal);
}

}  // namespace kse::sim
