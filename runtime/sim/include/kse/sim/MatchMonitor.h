#pragma once
// kse-match's live monitor (--monitor; protocol in docs/monitor.md): a MonitorServer fed by the
// match. Every client gets the match record, frames, events and the result; a client that
// subscribed to a robot also gets each transition segment it takes, as the engine takes it,
// and its active states after each decision cycle that changed them.
//
// It only reads the match, on the match's thread, and the wall clock: a match is the same
// with or without it (the log too, byte for byte).

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <kse/robot/MonitorServer.h>
#include <kse/sim/Match.h>

namespace kse::sim {

class MatchMonitor : public MatchObserver {
public:
	/** Listens at once (throws std::runtime_error when it cannot); add it to {@code match} as an observer. */
	MatchMonitor(const Match& match, robot::MonitorServer::Options options);
	explicit MatchMonitor(const Match& match) : MatchMonitor(match, robot::MonitorServer::Options{}) {}

	robot::MonitorServer& Server() { return server_; }

	/**
	 * Serves clients until {@code count} of those connected have subscribed or {@code limit} has
	 * passed (before the match starts: the only time the match waits for watchers). True when
	 * they did.
	 */
	bool WaitForSubscribers(std::size_t count, std::chrono::milliseconds limit);

	/** A match that cannot end (the supervisor's hang or signal): the "aborted" record, then the end. Any thread. */
	void Aborted(const std::string& reason, const std::string& robot, const std::string& detail);

	void OnStart(const Match& match) override;
	void OnFrame(const Match& match) override;
	void OnEvent(const Match& match, const MatchEvent& event) override;
	void OnEnd(const Match& match) override;
	void OnTransition(const Match& match, std::size_t robot, const statechart_engine::TransitionSegmentBase& transition) override;
	void OnDecision(const Match& match, std::size_t robot) override;
	void OnTick(const Match& match) override;

private:
	struct Robot {
		const robot::ChartIndex* index = nullptr;  // null for a scripted player
		const statechart_engine::Statechart* chart = nullptr;
		bool took = false;  // a transition in this decision cycle
	};

	std::string Active(std::size_t robot, double time) const;

	const Match& match_;
	std::vector<Robot> robots_;
	std::map<const statechart_engine::Definition*, std::unique_ptr<robot::ChartIndex>> indexes_;  // one per definition
	robot::MonitorServer server_;
	std::atomic<std::int64_t> centiseconds_{0};  // the match time, for Aborted() on another thread
};

}  // namespace kse::sim
