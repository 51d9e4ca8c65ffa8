#pragma once
// The game controller and referee of a simulated SPL game: the states INITIAL, READY, SET,
// PLAYING and FINISHED, kick-off, goals, the ball leaving the field, and penalties for leaving
// the field and for pushing. It can instead follow a real GameController's packets: a state in
// a packet is a state the robots follow, and the game is over only when the packets have said
// FINISHED after the first half for a while (GameOver(), runtime/README.md).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <kse/sim/World.h>

namespace kse::sim {

namespace gc {
struct GameControlData;
}

enum class GameState : std::uint8_t { Initial = 0, Ready = 1, Set = 2, Playing = 3, Finished = 4, Standby = 5 };
const char* ToString(GameState state);

enum class SetPlay : std::uint8_t { None = 0, GoalKick = 1, PushingFreeKick = 2, CornerKick = 3, KickIn = 4, PenaltyKick = 5 };

/** Penalties the simulated referee gives (numbers of the GameController protocol). */
namespace penalty {
constexpr int kNone = 0;
constexpr int kPlayerPushing = 2;
constexpr int kLeavingTheField = 6;
constexpr int kManual = 15;
}  // namespace penalty

struct RefereeConfig {
	double initial_seconds = 2;
	double ready_seconds = 45;     // the longest READY lasts
	bool end_ready_early = true;   // READY ends when every robot stands at its place
	double set_seconds = 5;
	double half_seconds = 600;     // of PLAYING
	int halves = 1;
	double penalty_seconds = 45;
	double pushing_seconds = 3;    // walking into a robot this long is pushing
	double game_stuck_seconds = 30;  // nobody touched the ball: kick-off again
	// following a GameController: FINISHED after the first half, held this long, ends the game
	double game_over_seconds = 5;
	double shoot_out_wait_seconds = 60;  // instead, while a penalty shoot-out or its next shot may still come
	double silence_seconds = 5;          // no packet this long is reported (once until packets come again)
};

/** Something the referee decided; Match logs it and tells the robots it carried. */
struct RefereeEvent {
	// Notice: something about the GameController's packets worth saying once (detail says what)
	enum class Type { State, Goal, BallOut, Penalty, Unpenalised, Placed, HalfTime, GameStuck, PenaltyShootOut, Notice } type;
	int team = -1;
	int body = -1;
	std::string detail;
};

class Referee {
public:
	explicit Referee(RefereeConfig config, int kicking_team = 0) : config_(config), kicking_team_(kicking_team) {
		secs_remaining_ = config.half_seconds;
	}

	/**
	 * Advances the game by dt. {@code ready_poses} are the field-frame kick-off poses of the
	 * bodies for the current kick-off (Match computes them). Returns what was decided.
	 */
	std::vector<RefereeEvent> Step(double dt, World& world, const std::vector<Pose2>& ready_poses);

	/** Skips to PLAYING with the robots at their kick-off poses and the ball at the centre. */
	std::vector<RefereeEvent> StartPlaying(World& world, const std::vector<Pose2>& ready_poses);

	/** From now on only a GameController's packets change the game; until the first comes, the robots wait in INITIAL. */
	void ListenToGameController() { listening_ = true; }
	bool Listening() const { return listening_; }
	/**
	 * Follows one GameController packet (and listens from now on): state, half, kick-off, scores,
	 * time and penalties come from it, values outside the protocol bounded and reported once
	 * each; {@code team_numbers} are the home and away teams' numbers, reported at once when a
	 * packet does not name them.
	 */
	std::vector<RefereeEvent> Follow(const gc::GameControlData& packet, const std::array<int, 2>& team_numbers, World& world,
	                                 const std::vector<Pose2>& ready_poses);
	/** A packet for our teams has been followed. */
	bool Following() const { return following_; }
	/**
	 * The game is over: FINISHED by our own referee, or, listening to a GameController, FINISHED
	 * after the first half (second half or penalty shoot-out) in every packet for
	 * game_over_seconds (shoot_out_wait_seconds while a shoot-out or its next shot may follow)
	 * and in at least two of them. One packet never ends a game.
	 */
	bool GameOver() const;
	bool PenaltyShootOut() const { return shoot_out_; }

	GameState State() const { return state_; }
	bool FirstHalf() const { return half_ == 1; }
	int Half() const { return half_; }
	/** 0 home, 1 away, -1 neither (a GameController may announce no kicking team). */
	int KickingTeam() const { return kicking_team_; }
	const std::array<int, 2>& Score() const { return score_; }
	double SecsRemaining() const { return secs_remaining_; }
	double SecondaryTime() const { return secondary_time_; }
	SetPlay CurrentSetPlay() const { return set_play_; }
	/** +1 when the team plays towards +x, -1 otherwise; teams change ends at half-time. */
	int Side(int team) const { return (team == 0) == (half_ % 2 == 1) ? 1 : -1; }

	int Penalty(int body) const { return Find(body).type; }
	double PenaltyRemaining(int body) const { return Find(body).remaining; }

	/** Where a robot comes back after a penalty: the sideline of its own half, facing the field. */
	Pose2 ReturnPose(const World& world, int body) const;
	/** In a penalty shoot-out: the kicker behind the penalty mark, the other team's robot on the goal line. */
	Pose2 PenaltyShotPose(int body_team) const;

	/** The bounds of the times the robots are told (s); a packet's value outside them is clamped. */
	static constexpr double kLongestTime = 3600;

private:
	struct Penalised {
		int body = -1;
		int type = penalty::kNone;
		double remaining = 0;
	};
	const Penalised& Find(int body) const;
	void Enter(GameState state, std::vector<RefereeEvent>& events);
	void PlaceForKickOff(World& world, const std::vector<Pose2>& ready_poses, bool only_illegal, std::vector<RefereeEvent>& events);
	void Penalise(World& world, int body, int type, double seconds, std::vector<RefereeEvent>& events);
	void Unpenalise(World& world, int body, std::vector<RefereeEvent>& events);
	void BallOut(World& world, std::vector<RefereeEvent>& events);
	void PlaceForPenaltyShot(World& world, std::vector<RefereeEvent>& events);
	std::vector<RefereeEvent> Listen(double dt);
	/** Each kind of notice is given once: a GameController sends the same packet twice a second. */
	void NoticeOnce(unsigned kind, int team, int body, std::string detail, std::vector<RefereeEvent>& events);
	double Bounded(const char* field, int value, unsigned kind, std::vector<RefereeEvent>& events);

	RefereeConfig config_;
	GameState state_ = GameState::Initial;
	double in_state_ = 0;
	int half_ = 1;
	int kicking_team_ = 0;
	int first_half_kicking_team_ = -1;
	std::array<int, 2> score_{0, 0};
	double secs_remaining_ = 0;
	double secondary_time_ = 0;
	SetPlay set_play_ = SetPlay::None;
	double untouched_ = 0;
	std::vector<Penalised> penalised_;
	bool following_ = false;
	bool listening_ = false;
	bool shoot_out_ = false;
	bool final_finished_ = false;  // the newest packet said FINISHED after the first half
	bool shoot_out_may_follow_ = false;
	int finished_packets_ = 0;     // in a row
	double finished_seconds_ = 0;
	double since_packet_ = 0;
	bool silence_reported_ = false;
	std::uint32_t noticed_ = 0;    // one bit per kind of notice given
};

}  // namespace kse::sim
