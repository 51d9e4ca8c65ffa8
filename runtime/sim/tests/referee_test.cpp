// The simulated game controller and referee: game states, goals and kick-off, the ball
// leaving the field, penalties, halves, and following a real GameController's packets.
#include <gtest/gtest.h>

#include <kse/sim/GameControlData.h>
#include <kse/sim/Referee.h>

using namespace kse::sim;

namespace {

constexpr double kDt = 0.01;

struct Game {
	World world{Random(1)};
	Referee referee;
	std::vector<Pose2> ready;
	std::vector<RefereeEvent> events;

	explicit Game(RefereeConfig config = {}, int robots_per_team = 0) : referee(config, 0) {
		for (int team = 0; team < 2; ++team) {
			for (int n = 1; n <= robots_per_team; ++n) {
				Body body;
				body.team = team;
				body.number = n;
				body.pose = {team == 0 ? -1.0 * n : 1.0 * n, 0.5, 0};
				world.bodies.push_back(body);
				ready.push_back(body.pose);
			}
		}
	}

	void Run(double seconds) {
		for (int i = 0; i < static_cast<int>(std::lround(seconds / kDt)); ++i) {
			world.Step(kDt);
			for (auto& event : referee.Step(kDt, world, ready)) events.push_back(event);
		}
	}

	bool Saw(RefereeEvent::Type type, const std::string& detail = "") const {
		for (const auto& event : events) {
			if (event.type == type && (detail.empty() || event.detail == detail)) return true;
		}
		return false;
	}
};

}  // namespace

TEST(Referee, RunsInitialReadySetPlayingFinished) {
	RefereeConfig config;
	config.half_seconds = 20;
	config.end_ready_early = false;
	config.ready_seconds = 10;
	Game game(config, 1);
	EXPECT_EQ(game.referee.State(), GameState::Initial);
	game.Run(config.initial_seconds + 0.01);
	EXPECT_EQ(game.referee.State(), GameState::Ready);
	game.Run(9.9);
	EXPECT_EQ(game.referee.State(), GameState::Ready);
	game.Run(0.1);
	EXPECT_EQ(game.referee.State(), GameState::Set);
	EXPECT_EQ(game.world.ball.position.Norm(), 0.0) << "the ball is placed at the centre";
	game.Run(config.set_seconds);
	EXPECT_EQ(game.referee.State(), GameState::Playing);
	game.Run(10);
	EXPECT_NEAR(game.referee.SecsRemaining(), 10, 0.02);
	game.Run(10.01);
	EXPECT_EQ(game.referee.State(), GameState::Finished);
}

TEST(Referee, ReadyEndsEarlyWhenEveryoneIsInPlace) {
	Game game({}, 2);
	game.Run(2.01);
	ASSERT_EQ(game.referee.State(), GameState::Ready);
	game.Run(3.1);
	EXPECT_EQ(game.referee.State(), GameState::Set) << "the robots stand at their kick-off poses already";
}

TEST(Referee, AGoalCountsAndTheOtherTeamKicksOff) {
	Game game({}, 1);
	game.referee.StartPlaying(game.world, game.ready);
	EXPECT_EQ(game.referee.KickingTeam(), 0);
	game.world.ball = Ball{{4.0, 0.2}, {2.5, 0}};  // home plays towards +x in the first half
	game.Run(1.0);
	EXPECT_EQ(game.referee.Score()[0], 1);
	EXPECT_EQ(game.referee.Score()[1], 0);
	EXPECT_EQ(game.referee.State(), GameState::Ready);
	EXPECT_EQ(game.referee.KickingTeam(), 1);
	EXPECT_TRUE(game.Saw(RefereeEvent::Type::Goal, "1:0"));
}

TEST(Referee, PlacesTheBallWhenItLeavesTheField) {
	Game game({}, 1);
	game.referee.StartPlaying(game.world, game.ready);
	game.world.ball = Ball{{1.0, 2.5}, {0, 2.0}};
	game.Run(1.0);
	EXPECT_TRUE(game.Saw(RefereeEvent::Type::BallOut, "kick-in"));
	EXPECT_NEAR(game.world.ball.position.y, field::kHalfWidth, 1e-9);
	EXPECT_EQ(game.referee.CurrentSetPlay(), SetPlay::KickIn);

	// attackers (home, towards +x) put it over the goal line: goal kick
	game.world.SetLastTouch(0);
	game.world.ball = Ball{{4.3, 1.5}, {2.0, 0}};
	game.Run(1.0);
	EXPECT_TRUE(game.Saw(RefereeEvent::Type::BallOut, "goal kick"));
	EXPECT_NEAR(game.world.ball.position.x, field::kHalfLength - field::kGoalAreaLength, 1e-9);

	// defenders (away) put it over their own goal line: corner kick
	game.world.SetLastTouch(1);
	game.world.ball = Ball{{4.3, -1.5}, {2.0, 0}};
	game.Run(1.0);
	EXPECT_TRUE(game.Saw(RefereeEvent::Type::BallOut, "corner kick"));
	EXPECT_NEAR(game.world.ball.position.x, field::kHalfLength, 1e-9);
	EXPECT_NEAR(game.world.ball.position.y, -field::kHalfWidth, 1e-9);
}

TEST(Referee, PenalisesLeavingTheFieldFor45Seconds) {
	Game game({}, 1);
	game.referee.StartPlaying(game.world, game.ready);
	game.world.bodies[0].pose = {-2.0, field::kHalfWidth + 0.2, 0};
	game.Run(0.02);
	EXPECT_EQ(game.referee.Penalty(0), penalty::kLeavingTheField);
	EXPECT_FALSE(game.world.bodies[0].on_field);
	game.Run(44.0);
	EXPECT_FALSE(game.world.bodies[0].on_field);
	game.Run(1.01);
	EXPECT_TRUE(game.world.bodies[0].on_field);
	EXPECT_EQ(game.referee.Penalty(0), penalty::kNone);
	EXPECT_NEAR(game.world.bodies[0].pose.x, -(field::kHalfLength - field::kPenaltyMarkDistance), 1e-9) << "back at its own half";
	EXPECT_NEAR(std::fabs(game.world.bodies[0].pose.y), field::kHalfWidth, 1e-9);
}

TEST(Referee, PenalisesPushing) {
	Game game({}, 1);
	game.referee.StartPlaying(game.world, game.ready);
	game.world.bodies[0].Place({-0.3, 1.0, 0});
	game.world.bodies[1].Place({0.0, 1.0, kPi});
	kse::robot::MotionCommands forward;
	forward.walk = true;
	forward.vx = 1;
	bool penalised = false;
	for (int i = 0; i < 600 && !penalised; ++i) {
		if (game.world.bodies[0].LegsFree()) game.world.bodies[0].Command(forward);
		game.Run(kDt);
		penalised = game.referee.Penalty(0) == penalty::kPlayerPushing;
	}
	// the pushed robot may fall first, which ends the pushing; then nobody is penalised
	EXPECT_TRUE(penalised || game.world.bodies[1].Fallen());
}

TEST(Referee, TwoHalvesChangeEnds) {
	RefereeConfig config;
	config.halves = 2;
	config.half_seconds = 5;
	Game game(config, 1);
	game.referee.StartPlaying(game.world, game.ready);
	EXPECT_EQ(game.referee.Side(0), 1);
	game.Run(5.01);
	EXPECT_TRUE(game.Saw(RefereeEvent::Type::HalfTime));
	EXPECT_EQ(game.referee.State(), GameState::Initial);
	EXPECT_FALSE(game.referee.FirstHalf());
	EXPECT_EQ(game.referee.Side(0), -1);
	EXPECT_EQ(game.referee.KickingTeam(), 1) << "the other team kicks off the second half";
}

TEST(Referee, KicksOffAgainWhenNobodyTouchesTheBall) {
	RefereeConfig config;
	config.game_stuck_seconds = 30;
	Game game(config, 1);
	game.referee.StartPlaying(game.world, game.ready);
	game.world.ball.position = {2.0, 2.0};
	game.Run(29.9);
	EXPECT_EQ(game.referee.State(), GameState::Playing);
	game.Run(0.2);
	EXPECT_TRUE(game.Saw(RefereeEvent::Type::GameStuck));
	EXPECT_EQ(game.referee.State(), GameState::Ready);
}

TEST(Referee, FollowsARealGameController) {
	Game game({}, 2);
	gc::GameControlData packet;
	packet.state = 3;
	packet.firstHalf = 1;
	packet.kickingTeam = 8;
	packet.secsRemaining = 321;
	packet.teams[0].teamNumber = 7;
	packet.teams[0].score = 2;
	packet.teams[1].teamNumber = 8;
	packet.teams[1].score = 1;
	packet.teams[1].players[1].penalty = 5;
	packet.teams[1].players[1].secsTillUnpenalised = 30;
	game.referee.Follow(packet, {7, 8}, game.world, game.ready);
	EXPECT_TRUE(game.referee.Following());
	EXPECT_EQ(game.referee.State(), GameState::Playing);
	EXPECT_EQ(game.referee.KickingTeam(), 1);
	EXPECT_EQ(game.referee.Score()[0], 2);
	EXPECT_EQ(game.referee.Score()[1], 1);
	EXPECT_NEAR(game.referee.SecsRemaining(), 321, 1e-9);
	EXPECT_EQ(game.referee.Penalty(3), 5) << "away player 2 is penalised";
	EXPECT_FALSE(game.world.bodies[3].on_field);

	game.Run(60);
	EXPECT_EQ(game.referee.State(), GameState::Playing) << "a followed game changes only with packets";
	EXPECT_FALSE(game.world.bodies[3].on_field) << "penalties end when the GameController says so";

	packet.teams[1].players[1].penalty = 0;
	packet.state = 4;
	game.referee.Follow(packet, {7, 8}, game.world, game.ready);
	EXPECT_TRUE(game.world.bodies[3].on_field);
	EXPECT_EQ(game.referee.State(), GameState::Finished);

	packet.kickingTeam = 255;  // no team kicks off
	game.referee.Follow(packet, {7, 8}, game.world, game.ready);
	EXPECT_EQ(game.referee.KickingTeam(), -1);

	gc::GameControlData other;
	other.teams[0].teamNumber = 1;
	other.teams[1].teamNumber = 2;
	other.state = 1;
	game.referee.Follow(other, {7, 8}, game.world, game.ready);
	EXPECT_EQ(game.referee.State(), GameState::Finished) << "packets of another game are ignored";
}
