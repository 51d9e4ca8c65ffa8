// The example behaviours on the simulated field, over many seeds: what a coach would check
// before a game. Each scenario is a GoogleTest case; ctest runs them in parallel.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include <kse/sim/Match.h>
#include <kse/sim/MatchLog.h>

using namespace kse::sim;

namespace {

constexpr int kSeeds = 20;

/** KSE_SCENARIO_LOGS=DIR keeps the JSON-lines log of every scenario run there, to see why one failed. */
class LogIfAsked {
public:
	LogIfAsked(Match& match, const std::string& name) {
		const char* folder = std::getenv("KSE_SCENARIO_LOGS");
		if (!folder) return;
		file_ = std::make_unique<std::ofstream>(std::string(folder) + "/" + name + ".jsonl");
		log_ = std::make_unique<JsonLinesLog>(*file_);
		match.AddObserver(*log_);
	}

private:
	std::unique_ptr<std::ofstream> file_;
	std::unique_ptr<JsonLinesLog> log_;
};

PlayerConfig Player(const std::string& behaviour, int number) { return {behaviour, number, std::nullopt, {}}; }

MatchConfig ThreeAgainstThree(std::uint64_t seed) {
	MatchConfig config;
	config.seed = seed;
	config.home.players = {Player("Goalie", 1), Player("Defender", 2), Player("Attacker", 3)};
	config.away.players = config.home.players;
	return config;
}

std::string Describe(const Match& match) {
	std::ostringstream text;
	for (const auto& event : match.Events()) {
		if (event.type == "state" || event.type == "kick" || event.type == "missed-kick" || event.type == "fall" || event.type == "dive" || event.type == "goal" ||
		    event.type == "stuck" || event.type == "penalty" || event.type == "ball-out") {
			text << "  " << Fixed(event.time, 2) << " " << event.type << " " << (event.robot >= 0 ? match.RobotId(static_cast<std::size_t>(event.robot)) : "")
			     << " " << event.detail << "\n";
		}
	}
	return text.str();
}

}  // namespace

TEST(Scenario, TheAttackerAloneScoresFromKickOffWithinAMinute) {
	int scored = 0;
	std::string failures;
	for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
		MatchConfig config;
		config.seed = seed;
		config.start_playing = true;
		config.home.players = {Player("Attacker", 2)};
		Match match(config);
		LogIfAsked log(match, "attacker-" + std::to_string(seed));
		while (match.Time() < 60 && match.GetReferee().Score()[0] == 0) match.Step();
		if (match.GetReferee().Score()[0] > 0) {
			++scored;
		} else {
			failures += "seed " + std::to_string(seed) + ":\n" + Describe(match);
		}
		EXPECT_EQ(match.Failures(), 0u);
	}
	std::cout << "[ scenario ] Attacker scored within 60 s in " << scored << " of " << kSeeds << " seeds\n";
	EXPECT_GE(scored, 19) << failures;
}

TEST(Scenario, TheGoalieStopsPenaltyShots) {
	int saved = 0;
	std::string failures;
	for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
		MatchConfig config;
		config.seed = seed;
		config.start_playing = true;
		config.home.players = {Player("Goalie", 1)};
		Match match(config);
		LogIfAsked log(match, "goalie-" + std::to_string(seed));
		match.Step();
		// the ball on the penalty mark in front of the home goal; the goalkeeper sees it first
		const Vec2 mark{-(field::kHalfLength - field::kPenaltyMarkDistance), 0};
		match.GetWorld().ball = Ball{mark, {}};
		while (match.Time() < 3) match.Step();
		// a straight shot at a point inside the goal, as hard as a Nao kicks
		Random shooter(seed * 7919);
		const Vec2 target{-field::kHalfLength, shooter.Uniform(-0.7, 0.7)};
		const double direction = (target - mark).Angle();
		match.GetWorld().ball.velocity = World::KickVelocity(shooter.Uniform(3.0, 4.5), direction);
		match.GetWorld().SetLastTouch(-1);
		while (match.Time() < 7 && match.GetReferee().Score()[1] == 0) match.Step();
		if (match.GetReferee().Score()[1] == 0) {
			++saved;
		} else {
			failures += "seed " + std::to_string(seed) + " (aimed at y " + Fixed(target.y, 2) + "):\n" + Describe(match);
		}
	}
	std::cout << "[ scenario ] Goalie saved " << saved << " of " << kSeeds << " penalty shots\n";
	EXPECT_GE(saved, 18) << failures;
}

class FullHalf : public ::testing::TestWithParam<int> {};

TEST_P(FullHalf, ThreeAgainstThreePlayATenMinuteHalfWithoutACrashOrAStuckRobot) {
	// the seeds of this shard: GetParam(), GetParam() + 4, ... (the line-up of kse demo)
	int seeds = 0;
	int scored = 0;
	for (int seed = GetParam(); seed <= kSeeds; seed += 4) {
		Match match(ThreeAgainstThree(static_cast<std::uint64_t>(seed)));
		LogIfAsked log(match, "3v3-" + std::to_string(seed));
		match.Run(0);
		EXPECT_EQ(match.GetReferee().State(), GameState::Finished) << "seed " << seed;
		EXPECT_EQ(match.StuckCount(), 0u) << "seed " << seed << "\n" << Describe(match);
		EXPECT_EQ(match.Failures(), 0u) << "seed " << seed;
		const auto& score = match.GetReferee().Score();
		std::size_t kicks = 0;
		for (const auto& event : match.Events()) kicks += event.type == "kick";
		EXPECT_GT(kicks, 10u) << "seed " << seed << ": they play the ball";
		++seeds;
		scored += score[0] + score[1] > 0 ? 1 : 0;
		std::cout << "[ scenario ] seed " << seed << ": " << score[0] << ":" << score[1] << " after " << Fixed(match.Time(), 0) << " s, " << kicks
		          << " kicks\n";
	}
	EXPECT_GE(scored, seeds - 1) << "a half is not a 0:0 stand-off, but in at most one seed of " << seeds;
}

INSTANTIATE_TEST_SUITE_P(Seeds, FullHalf, ::testing::Values(1, 2, 3, 4));

TEST(Scenario, TheSameSeedGivesTheSameLogByteForByte) {
	auto log = [](std::uint64_t seed) {
		std::ostringstream text;
		JsonLinesLog json(text);
		MatchConfig config = ThreeAgainstThree(seed);
		config.referee.half_seconds = 120;
		Match match(config);
		match.AddObserver(json);
		match.Run(0);
		return text.str();
	};
	for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
		const std::string first = log(seed);
		ASSERT_EQ(first, log(seed)) << "seed " << seed;
		ASSERT_NE(first.find("\"type\":\"result\""), std::string::npos);
	}
}
