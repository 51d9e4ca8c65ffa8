// Whole matches with small test behaviours: determinism of the log, its content, the picture,
// team frames, and the stuck-robot watch.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include <kse/sim/GameControlData.h>
#include <kse/sim/GameControllerLink.h>
#include <kse/sim/Match.h>
#include <kse/sim/MatchLog.h>

#include "test_behaviours.h"

using namespace kse::sim;

namespace {

MatchConfig Chasers(std::uint64_t seed, int per_team = 2) {
	MatchConfig config;
	config.seed = seed;
	config.start_playing = true;
	for (int n = 1; n <= per_team; ++n) {
		config.home.players.push_back({"Chaser", n, std::nullopt, {}});
		config.away.players.push_back({"Chaser", n, std::nullopt, {}});
	}
	return config;
}

std::string Log(const MatchConfig& config, double seconds) {
	std::ostringstream text;
	JsonLinesLog log(text);
	Match match(config);
	match.AddObserver(log);
	match.Run(seconds);
	return text.str();
}

std::vector<std::string> Lines(const std::string& text) {
	std::vector<std::string> lines;
	std::istringstream in(text);
	for (std::string line; std::getline(in, line);) lines.push_back(line);
	return lines;
}

std::size_t Count(const std::string& text, const std::string& part) {
	std::size_t count = 0;
	for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
	return count;
}

}  // namespace

TEST(Match, TheSameSeedGivesTheSameLogByteForByte) {
	const std::string first = Log(Chasers(42), 60);
	const std::string second = Log(Chasers(42), 60);
	ASSERT_GT(first.size(), 100000u);
	EXPECT_EQ(first, second);
	EXPECT_NE(first, Log(Chasers(43), 60)) << "another seed, another match";
}

TEST(Match, TheLogHasTheMatchFramesEventsAndResult) {
	const auto lines = Lines(Log(Chasers(7), 30));
	ASSERT_GT(lines.size(), 300u);
	EXPECT_EQ(lines.front().rfind("{\"type\":\"match\",\"version\":1,\"seed\":7,", 0), 0u) << lines.front();
	EXPECT_NE(lines.front().find("\"behaviour\":\"Chaser\""), std::string::npos);
	EXPECT_EQ(lines.back().rfind("{\"type\":\"result\",\"t\":30.00,", 0), 0u) << lines.back();
	std::size_t frames = 0;
	for (const auto& line : lines) {
		ASSERT_EQ(line.front(), '{');
		ASSERT_EQ(line.back(), '}');
		if (line.rfind("{\"type\":\"frame\"", 0) != 0) continue;
		++frames;
		EXPECT_EQ(Count(line, "\"pose\":["), 4u);
		EXPECT_EQ(Count(line, "\"active\":[\"Node_chaser\",\"Node_Chase\"]"), 4u) << line;
	}
	EXPECT_EQ(frames, 300u) << "a frame every 0.1 s";
	const std::string all = Log(Chasers(7), 30);
	EXPECT_NE(all.find("\"taken\":[\"Node_Chase_TO_Node_Chase\""), std::string::npos) << "transitions taken are logged";
	EXPECT_NE(all.find("\"event\":\"state\",\"detail\":\"PLAYING\""), std::string::npos);
}

TEST(Match, AChaserKicksTheBallTowardsTheGoal) {
	MatchConfig config = Chasers(3, 1);
	config.away.players.clear();
	Match match(config);
	double farthest = 0;
	int kicks = 0;
	while (match.Time() < 90 && match.GetReferee().Score()[0] == 0) {
		match.Step();
		farthest = std::max(farthest, match.GetWorld().ball.position.x);
		for (const auto& event : match.GetWorld().Events()) kicks += event.type == PhysicsEvent::Type::Kick;
	}
	EXPECT_GT(kicks, 0);
	EXPECT_GT(farthest, 1.5);
	EXPECT_EQ(match.Failures(), 0u);
}

TEST(Match, TeamsSeeTheFieldFromTheirOwnEnd) {
	MatchConfig config;
	config.start_playing = true;
	kse::robot::Perception seen_home, seen_away;
	config.home.players.push_back({"", 1, std::nullopt, [&](const kse::robot::Perception& p) { seen_home = p; return kse::robot::MotionCommands{}; }});
	config.away.players.push_back({"", 1, std::nullopt, [&](const kse::robot::Perception& p) { seen_away = p; return kse::robot::MotionCommands{}; }});
	Match match(config);
	match.Run(1);
	EXPECT_NEAR(match.GetWorld().bodies[0].pose.x, -4.35, 1e-9);
	EXPECT_NEAR(match.GetWorld().bodies[1].pose.x, 4.35, 1e-9);
	EXPECT_NEAR(seen_home.estimate.x, -4.35, 0.2);
	EXPECT_NEAR(seen_away.estimate.x, -4.35, 0.2) << "the away team's own goal is at -x in its frame too";
	EXPECT_NEAR(std::fabs(seen_away.estimate.theta), 0.0, 0.2);
	EXPECT_EQ(seen_home.player_state, 3);
	EXPECT_TRUE(seen_home.kickoff);
	EXPECT_FALSE(seen_away.kickoff);
	EXPECT_EQ(seen_away.team_number, 8);
}

TEST(Match, AStatechartThatStopsIsReportedStuck) {
	MatchConfig config;
	config.start_playing = true;
	config.home.players.push_back({"Sleeper", 1, std::nullopt, {}});
	config.away.players.push_back({"Chaser", 1, std::nullopt, {}});
	Match match(config);
	match.Run(9);
	EXPECT_EQ(match.StuckCount(), 0u);
	match.Run(2);
	EXPECT_EQ(match.StuckCount(), 1u);
	bool reported = false;
	for (const auto& event : match.Events()) reported = reported || (event.type == "stuck" && event.robot == 0 && event.detail == "no transition");
	EXPECT_TRUE(reported);
}

TEST(Match, ALoopWhoseOnlyWaitIsItsActivityGoesRoundOncePerDecisionCycle) {
	// runner = Wake.Chase~ : on a robot each Chase run takes time on a worker; in the simulator
	// it lasts until the robot's next decision cycle, so the robot plays instead of spinning.
	MatchConfig config;
	config.start_playing = true;
	config.home.players.push_back({"Runner", 1, std::nullopt, {}});
	config.away.players.clear();
	std::ostringstream text;
	JsonLinesLog log(text);
	Match match(config);
	match.AddObserver(log);
	match.Run(10);
	EXPECT_EQ(match.FailedCount(), 0u);
	EXPECT_EQ(match.StuckCount(), 0u);
	const std::string all = text.str();
	EXPECT_EQ(all.find("\"event\":\"failed\""), std::string::npos);
	// about one round of the loop (two segments: into the connector, back to Chase) per cycle
	const std::size_t rounds = Count(all, "\"Node_0_3_3_TO_Node_Chase\"");
	const double cycles = 10 / (Match::kTick * Match::kTicksPerFrame);
	EXPECT_GT(rounds, cycles * 0.9) << "a round in (almost) every decision cycle";
	EXPECT_LE(rounds, cycles + 1) << "never more than one round per decision cycle";
	EXPECT_GT(match.GetWorld().bodies[0].pose.x, -4.0) << "the runner walked (towards the ball)";
}

TEST(Match, ARobotGoingRoundALoopWithoutWaitingFailsAndTheMatchGoesOn) {
	MatchConfig config;
	config.start_playing = true;
	config.home.players.push_back({"Spinner", 1, std::nullopt, {}});
	config.away.players.push_back({"Chaser", 1, std::nullopt, {}});
	std::ostringstream text;
	JsonLinesLog log(text);
	Match match(config);
	match.AddObserver(log);
	match.Run(20);
	EXPECT_EQ(match.Time(), 20.0) << "the match went on to its end";
	EXPECT_EQ(match.FailedCount(), 1u);
	EXPECT_EQ(match.StuckCount(), 0u) << "a failed robot is not reported stuck as well";
	std::size_t failed = 0;
	for (const auto& event : match.Events()) {
		if (event.type != "failed") continue;
		++failed;
		EXPECT_EQ(event.robot, 0);
		EXPECT_LT(event.time, 0.1);
		EXPECT_EQ(event.detail, "the statechart took 10000 transitions in one decision cycle, round 0.2 'Node_Look' -> 0.3 'Node_0_3' -> "
		                        "0.2 'Node_Look', without waiting for an activity or a timer");
	}
	EXPECT_EQ(failed, 1u) << "reported once";
	const auto lines = Lines(text.str());
	EXPECT_NE(text.str().find("\"event\":\"failed\",\"team\":0,\"robot\":\"home-1\""), std::string::npos);
	EXPECT_NE(lines.back().find("\"failed\":1"), std::string::npos) << lines.back();
	EXPECT_GT(Count(text.str(), "\"Node_Chase_TO_Node_Chase\""), 150u) << "the other robot played on (a round every 100 ms)";
}

TEST(Match, AFullGameGoesThroughTheStatesAndThePictureShowsIt) {
	MatchConfig config = Chasers(5);
	config.start_playing = false;
	config.referee.half_seconds = 60;
	Match match(config);
	SvgPicture picture;
	match.AddObserver(picture);
	match.Run(0);
	EXPECT_EQ(match.GetReferee().State(), GameState::Finished);
	std::vector<std::string> states;
	for (const auto& event : match.Events()) {
		if (event.type == "state") states.push_back(event.detail);
	}
	ASSERT_GE(states.size(), 5u);
	EXPECT_EQ(states[0], "INITIAL");
	EXPECT_EQ(states[1], "READY");
	EXPECT_EQ(states[2], "SET");
	EXPECT_EQ(states[3], "PLAYING");
	EXPECT_EQ(states.back(), "FINISHED");
	std::ostringstream svg;
	picture.Write(svg);
	const std::string text = svg.str();
	EXPECT_EQ(text.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
	EXPECT_EQ(Count(text, "<path fill=\"none\" stroke=\"#1f5fd6\""), 2u) << "a path for each home robot";
	EXPECT_EQ(Count(text, "<path fill=\"none\" stroke=\"#d62f2f\""), 2u);
	EXPECT_NE(text.find("stroke=\"#ff9900\""), std::string::npos) << "the ball's path";
	EXPECT_NE(text.find("</svg>"), std::string::npos);
}

TEST(Match, FollowsARealGameControllerAndAnswersIt) {
	// a socket standing in for the GameController: it sends packets and receives the answers
	const int controller = ::socket(AF_INET, SOCK_DGRAM, 0);
	sockaddr_in address{};
	address.sin_family = AF_INET;
	address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
	ASSERT_EQ(::bind(controller, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
	socklen_t length = sizeof address;
	::getsockname(controller, reinterpret_cast<sockaddr*>(&address), &length);
	gc::GameControllerLink link({"127.0.0.1", 0, ntohs(address.sin_port)});

	MatchConfig config = Chasers(1, 1);
	Match match(config);
	match.Listen(link);
	gc::GameControlData packet;
	packet.state = gc::kStatePlaying;
	packet.firstHalf = 1;
	packet.kickingTeam = 8;
	packet.secsRemaining = 500;
	packet.teams[0].teamNumber = 7;
	packet.teams[1].teamNumber = 8;
	packet.teams[1].score = 2;
	const auto bytes = gc::Encode(packet);
	sockaddr_in to{};
	to.sin_family = AF_INET;
	to.sin_port = htons(link.ListenPort());
	to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
	ASSERT_EQ(::sendto(controller, bytes.data(), bytes.size(), 0, reinterpret_cast<sockaddr*>(&to), sizeof to), 118);
	const std::uint8_t garbage[3] = {1, 2, 3};
	::sendto(controller, garbage, sizeof garbage, 0, reinterpret_cast<sockaddr*>(&to), sizeof to);

	for (int i = 0; i < 200 && !match.GetReferee().Following(); ++i) {
		match.Step();
		::usleep(1000);
	}
	ASSERT_TRUE(match.GetReferee().Following());
	match.Run(1.0);
	EXPECT_EQ(match.GetReferee().State(), GameState::Playing);
	EXPECT_EQ(match.GetReferee().KickingTeam(), 1);
	EXPECT_EQ(match.LastPerception(1).our_score, 2);
	EXPECT_EQ(match.LastPerception(0).player_state, 3);
	EXPECT_EQ(link.Malformed(), 1u) << "the garbage was counted and ignored";

	int answers = 0;
	std::uint8_t buffer[256];
	for (ssize_t size; (size = ::recv(controller, buffer, sizeof buffer, MSG_DONTWAIT)) > 0;) {
		const auto status = gc::DecodeReturnData(buffer, static_cast<std::size_t>(size));
		ASSERT_TRUE(status.has_value());
		EXPECT_TRUE(status->teamNum == 7 || status->teamNum == 8);
		EXPECT_EQ(status->playerNum, 1);
		++answers;
	}
	EXPECT_GE(answers, 4) << "each robot answers twice a second";
	::close(controller);
}
