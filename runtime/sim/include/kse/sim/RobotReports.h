#pragma once
// What the robots' engines report during a match (failures of behaviour code, calls the
// watchdog finds running too long, warnings), as lines that name the robot, with repeats
// rate-limited: a behaviour that throws in every cycle gives a few lines and then a count a
// second, not one line per throw.

#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>

#include <statechart_engine/Statechart.h>

namespace kse::sim {

/** One report of one robot's engine. */
struct RobotReport {
	const std::string& robot;      // "home-2": team and player number, as in the log
	const std::string& behaviour;  // "Defender"
	const statechart_engine::EngineReport& report;
};

class RobotReports {
public:
	/** Gets each line, without '\n', one at a time (standard error by default). */
	using Printer = std::function<void(const std::string& line)>;
	/** Gets every report before rate limiting, on the thread that reported (e.g. to end a match whose robot hangs). */
	using Listener = std::function<void(const RobotReport&)>;

	struct Limits {
		std::size_t first = 3;                    // identical messages of one robot printed in full
		std::chrono::milliseconds period{1000};  // then one line a period counting the repeats
	};

	RobotReports();
	explicit RobotReports(Limits limits);
	void SetPrinter(Printer printer);
	void SetListener(Listener listener);

	/**
	 * A reporter for one robot's engine: its lines read "[home-2 Defender] statechart 'X': ...".
	 * It stays valid after this object is gone (an engine stuck in a call may report late).
	 */
	statechart_engine::Reporter For(const std::string& robot, const std::string& behaviour);

	/** Prints the repeats not counted yet; a match calls it at its end. */
	void Flush();
	/** Lines printed, and reports not printed (counted in the repeat lines instead). */
	std::size_t Printed() const;
	std::size_t Suppressed() const;

private:
	struct Shared;
	std::shared_ptr<Shared> shared_;
};

}  // namespace kse::sim
