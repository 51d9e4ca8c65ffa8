#pragma once
// A simulated SPL match: the world, the referee, and one behaviour process (kse::robot) per
// robot, stepped in 10 ms ticks; each robot perceives and runs its statechart every third tick
// (one camera image, 33 per second). Deterministic for a seed: the clock is simulated and the
// activities run inline.

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <kse/messaging/Clock.h>
#include <kse/robot/Robot.h>
#include <kse/sim/Perception.h>
#include <kse/sim/Referee.h>
#include <kse/sim/RobotReports.h>
#include <kse/sim/World.h>

namespace kse::sim {

namespace gc {
class GameControllerLink;
struct GameControlData;
}

/** A controller instead of a statechart: scripted players, and the benchmark's baseline. */
using Controller = std::function<robot::MotionCommands(const robot::Perception&)>;

struct PlayerConfig {
	std::string behaviour;  // a registered statechart, e.g. "Goalie"
	int number = 1;         // 1 is the goalkeeper
	std::optional<Pose2> ready;  // kick-off pose in the team frame (own goal at -x); a default by number otherwise
	Controller controller;  // used when set, instead of the statechart
};

struct TeamConfig {
	int number = 0;  // team number (GameController)
	std::string name;
	std::vector<PlayerConfig> players;
};

struct MatchConfig {
	std::uint64_t seed = 1;
	TeamConfig home{7, "home", {}};
	TeamConfig away{8, "away", {}};
	RefereeConfig referee;
	int kicking_team = 0;
	/** Start in PLAYING with the robots at their kick-off poses instead of INITIAL. */
	bool start_playing = false;
	/** Log frames this often (s). */
	double frame_period = 0.1;
	/** Seconds without a transition (or pinned while walking) after which a robot counts as stuck. */
	double stuck_seconds = 10;
};

/** Anything worth a line in the log. */
struct MatchEvent {
	double time = 0;
	std::string type;  // state, goal, ball-out, penalty, unpenalised, placed, half-time, game-stuck, penalty-shoot-out, gamecontroller, kick, missed-kick, fall, stuck, failed
	int team = -1;
	int robot = -1;
	std::string detail;
};

class Match;

/** Watches a match: logs, pictures, live views. */
class MatchObserver {
public:
	virtual ~MatchObserver() = default;
	virtual void OnStart(const Match&) {}
	virtual void OnFrame(const Match&) {}
	virtual void OnEvent(const Match&, const MatchEvent&) {}
	virtual void OnEnd(const Match&) {}
	/**
	 * A transition segment {@code robot}'s statechart took, as the engine takes it (inside the
	 * robot's decision cycle): the one observer slot of the statechart is the match's, which
	 * passes each segment on to every match observer.
	 */
	virtual void OnTransition(const Match&, std::size_t /*robot*/, const statechart_engine::TransitionSegmentBase&) {}
	/** After a robot's decision cycle (each robot has one every kTicksPerFrame ticks). */
	virtual void OnDecision(const Match&, std::size_t /*robot*/) {}
	/** At the end of every tick (10 ms of match time): where a live view does its I/O. */
	virtual void OnTick(const Match&) {}
};

class Match {
public:
	static constexpr double kTick = 0.01;   // s of simulated time a Step() advances
	static constexpr int kTicksPerFrame = 3;  // a robot perceives and decides every third tick

	explicit Match(MatchConfig config);
	~Match();
	Match(const Match&) = delete;
	Match& operator=(const Match&) = delete;

	void AddObserver(MatchObserver& observer) { observers_.push_back(&observer); }
	/** Follows a real GameController's packets (only them: the robots wait in INITIAL for the first) and answers it for every robot. */
	void Listen(gc::GameControllerLink& link);
	/** Follows one GameController packet, as the link does with each it accepts. */
	void Follow(const gc::GameControlData& packet);

	/** One tick. The first call starts the match (observers see OnStart). */
	void Step();
	/**
	 * Steps until the game is over (Referee::GameOver) or {@code seconds} of simulated time have
	 * passed; observers see OnEnd. {@code speed}: match seconds per wall-clock second (1: real
	 * time, 10: ten times as fast); 0, as fast as it can. Pacing only waits between ticks, so the
	 * match is the same at any speed.
	 */
	void Run(double seconds, const std::function<void(const Match&)>& progress = {}, double speed = 0);
	void End();

	// what observers and tests read
	double Time() const { return static_cast<double>(ticks_) * kTick; }
	std::uint64_t Ticks() const { return ticks_; }
	const MatchConfig& Config() const { return config_; }
	World& GetWorld() { return world_; }
	const World& GetWorld() const { return world_; }
	Referee& GetReferee() { return referee_; }
	const Referee& GetReferee() const { return referee_; }
	std::size_t RobotCount() const { return players_.size(); }
	/** "home-1", "away-5": team and player number. */
	const std::string& RobotId(std::size_t robot) const { return players_[robot]->id; }
	const std::string& Behaviour(std::size_t robot) const { return players_[robot]->config.behaviour; }
	const TeamConfig& Team(int team) const { return team == 0 ? config_.home : config_.away; }
	std::vector<std::string> ActiveStates(std::size_t robot) const;
	/** Transitions the robot's statechart took since the last frame (their names, which live as long as the match). */
	const std::vector<const std::string*>& TransitionsSinceFrame(std::size_t robot) const { return players_[robot]->taken; }
	const robot::Perception& LastPerception(std::size_t robot) const { return players_[robot]->perception; }
	const RobotSense& Sense(std::size_t robot) const { return players_[robot]->sense; }
	/** The robot's behaviour process, or null for a robot played by a Controller. */
	const robot::Robot* GetRobot(std::size_t robot) const { return players_[robot]->robot.get(); }
	robot::Robot* GetRobot(std::size_t robot) { return players_[robot]->robot.get(); }
	/** Kick-off pose of a robot, field frame, for the current kick-off. */
	Pose2 ReadyPose(std::size_t robot) const;
	/** Field pose from a team's frame and back (the same mapping both ways). */
	Pose2 TeamFrame(int team, const Pose2& pose) const;

	const std::vector<MatchEvent>& Events() const { return events_; }
	std::size_t StuckCount() const { return stuck_; }
	/** Robots whose behaviour failed for good (robot::Robot::Failed()): they stand still. */
	std::size_t FailedCount() const { return failed_; }
	std::size_t Failures() const;
	/** Wall-clock seconds spent in the robots' statecharts (perception published, run, commands read). */
	double EngineSeconds() const { return engine_seconds_; }
	/** What the robots' engines report, each line naming its robot ("[home-2 Defender] ..."), repeats rate-limited. */
	RobotReports& Reports() { return reports_; }
	/** "home-2 Defender" while a match runs that robot's behaviour, else null; for a crash handler (any thread). */
	static const char* ThinkingRobot() noexcept;

private:
	struct Player {
		PlayerConfig config;
		std::string id;
		std::string label;  // id and behaviour, as messages name the robot
		std::unique_ptr<robot::Robot> robot;
		RobotSense sense;
		robot::Perception perception;
		std::vector<const std::string*> taken;  // names of the transitions, not copies: a robot takes about one a cycle
		double last_transition = 0;
		double pinned = 0;
		Vec2 last_position;
		bool stuck = false;
		bool failed = false;
		Player(PlayerConfig c, std::string i, Random random) : config(std::move(c)), id(std::move(i)), sense(random) {}
	};

	void Start();
	void Think(std::size_t robot);
	void Emit(MatchEvent event);
	void Apply(const std::vector<RefereeEvent>& events);
	void WatchForStuck(std::size_t robot);
	const std::vector<Pose2>& ReadyPoses() const;
	void ExchangeWithGameController();

	MatchConfig config_;
	messaging::ManualClock clock_;
	Random random_;
	World world_;
	Random camera_random_{0};
	Referee referee_;
	std::vector<std::unique_ptr<Player>> players_;
	std::vector<MatchObserver*> observers_;
	RobotReports reports_;
	std::vector<MatchEvent> events_;
	gc::GameControllerLink* link_ = nullptr;
	std::uint64_t ticks_ = 0;
	bool started_ = false;
	bool ended_ = false;
	std::size_t stuck_ = 0;
	std::size_t failed_ = 0;
	double engine_seconds_ = 0;
	mutable std::vector<Pose2> ready_poses_;  // ReadyPoses(), for ready_key_
	mutable std::array<int, 3> ready_key_{};  // kicking team, sides of the teams
};

/** The default kick-off pose of a player number, team frame; the kick-off taker stands at the centre. */
Pose2 DefaultReadyPose(int number, bool takes_kick_off);

}  // namespace kse::sim
