#include <kse/sim/MatchMonitor.h>

#include <cmath>
#include <thread>

#include <kse/sim/MatchLog.h>

namespace kse::sim {

namespace {

std::vector<std::string> RobotIds(const Match& match) {
	std::vector<std::string> ids;
	for (std::size_t i = 0; i < match.RobotCount(); ++i) ids.push_back(match.RobotId(i));
	return ids;
}

}  // namespace

MatchMonitor::MatchMonitor(const Match& match, robot::MonitorServer::Options options)
	: match_(match), robots_(match.RobotCount()), server_(RobotIds(match), std::move(options)) {
	std::string welcome = "{\"type\":\"match\",\"monitor\":1," + MatchRecordFields(match) + ",\"robots\":[";
	for (std::size_t i = 0; i < match.RobotCount(); ++i) {
		Robot& robot = robots_[i];
		if (const robot::Robot* process = match.GetRobot(i)) {
			// Chart() is not const, but nothing here changes it: the monitor only reads
			robot.chart = &const_cast<robot::Robot*>(process)->Chart();
			auto& index = indexes_[&robot.chart->GetDefinition()];
			if (!index) index = std::make_unique<robot::ChartIndex>(robot.chart->GetDefinition());
			robot.index = index.get();
		}
		welcome += i ? ",{\"id\":" : "{\"id\":";
		robot::AppendJsonString(welcome, match.RobotId(i));
		welcome += ",\"behaviour\":";
		robot::AppendJsonString(welcome, match.Behaviour(i));
		welcome += ",\"states\":" + std::to_string(robot.index ? robot.index->StateCount() : 0);
		welcome += ",\"transitions\":" + std::to_string(robot.index ? robot.index->TransitionCount() : 0) + "}";
	}
	welcome += "]}";
	server_.SetWelcome(std::move(welcome));
	server_.OnSubscribed([this](std::size_t client, std::size_t robot) { server_.SendTo(client, Active(robot, match_.Time())); });
	server_.OnBlackboard([this](std::size_t client, std::size_t robot) {
		const robot::Robot* process = match_.GetRobot(robot);
		if (process == nullptr) {
			server_.SendTo(client, robot::BlackboardRefusal(match_.RobotId(robot), "this robot runs no statechart"));
			return;
		}
		server_.SendTo(client, robot::BlackboardRecord(match_.Time(), match_.RobotId(robot), process->Hub()));
	});
}

std::string MatchMonitor::Active(std::size_t robot, double time) const {
	const Robot& r = robots_[robot];
	if (!r.index) {
		std::string line = "{\"type\":\"active\",\"t\":" + Fixed(time, 2) + ",\"robot\":";
		robot::AppendJsonString(line, match_.RobotId(robot));
		return line + ",\"active\":[]}";
	}
	return robot::ActiveRecord(time, match_.RobotId(robot), *r.index, *r.chart);
}

bool MatchMonitor::WaitForSubscribers(std::size_t count, std::chrono::milliseconds limit) {
	const auto deadline = std::chrono::steady_clock::now() + limit;
	for (;;) {
		server_.Pump();
		if (server_.Subscribers() >= count) return true;
		if (std::chrono::steady_clock::now() >= deadline) return false;
		std::this_thread::sleep_for(std::chrono::milliseconds(10));
	}
}

void MatchMonitor::Aborted(const std::string& reason, const std::string& robot, const std::string& detail) {
	server_.SendAll(AbortedRecord(static_cast<double>(centiseconds_.load(std::memory_order_relaxed)) / 100, reason, robot, detail));
	server_.Finish(std::chrono::seconds(1));
}

void MatchMonitor::OnStart(const Match&) { server_.Pump(); }

void MatchMonitor::OnFrame(const Match& match) {
	const auto& score = match.GetReferee().Score();
	server_.SendAll("{\"type\":\"frame\",\"t\":" + Fixed(match.Time(), 2) + ",\"state\":\"" + ToString(match.GetReferee().State()) +
	                "\",\"score\":[" + std::to_string(score[0]) + "," + std::to_string(score[1]) + "]}");
}

void MatchMonitor::OnEvent(const Match& match, const MatchEvent& event) { server_.SendAll(EventRecord(match, event)); }

void MatchMonitor::OnEnd(const Match& match) {
	server_.SendAll(ResultRecord(match));
	server_.Finish();
}

void MatchMonitor::OnTransition(const Match& match, std::size_t robot, const statechart_engine::TransitionSegmentBase& transition) {
	Robot& r = robots_[robot];
	r.took = true;
	// a record is made only for a robot somebody watches: unwatched, a transition costs a check
	if (!r.index || !server_.Wants(robot)) return;
	server_.Send(robot, robot::TakenRecord(match.Time(), robot::WallMilliseconds(), match.RobotId(robot), r.index->Of(transition), transition));
}

void MatchMonitor::OnDecision(const Match& match, std::size_t robot) {
	Robot& r = robots_[robot];
	if (!r.took) return;
	r.took = false;
	if (server_.Wants(robot)) server_.Send(robot, Active(robot, match.Time()));
}

void MatchMonitor::OnTick(const Match& match) {
	centiseconds_.store(std::llround(match.Time() * 100), std::memory_order_relaxed);
	server_.Pump();
}

}  // namespace kse::sim
