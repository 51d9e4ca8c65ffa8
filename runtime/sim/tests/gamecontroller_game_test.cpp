// Following a whole game of a GameController: real UDP packets on loopback, sent as
// GameController3 sends them (2 a second: here one every 0.5 s of match time, so a game's
// minutes pass in a fraction of a second), through the link into a match of four Chasers.
// Each test is named after the fix of issue 13 it guards.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <kse/sim/GameControlData.h>
#include <kse/sim/GameControllerLink.h>
#include <kse/sim/Match.h>

#include "loopback_udp.h"
#include "test_behaviours.h"

using namespace kse::sim;

namespace {

constexpr int kHome = 7, kAway = 8;
constexpr int kTicksPerPacket = 50;  // GameController3 sends twice a second

using UdpSender = test_support::LoopbackUdp;

/** The packets GameController3 sends for a play-off game of teams 7 (home) and 8 (away), two robots each, and its actions. */
struct GameController3 {
	gc::GameControlData packet;

	GameController3() {
		packet.playersPerTeam = 2;
		packet.competitionPhase = 1;  // play-off: a drawn game goes to a penalty shoot-out
		packet.firstHalf = 1;
		packet.kickingTeam = kHome;
		packet.secsRemaining = 600;
		packet.teams[0].teamNumber = kHome;
		packet.teams[1].teamNumber = kAway;
		for (auto& team : packet.teams) {
			team.goalkeeper = 1;
			team.messageBudget = 1200;
		}
		packet.teams[1].fieldPlayerColour = 1;
	}
	gc::TeamInfo& Team(int number) { return packet.teams[0].teamNumber == number ? packet.teams[0] : packet.teams[1]; }
	void State(std::uint8_t state) { packet.state = state; }
	/** The half-time break's end: teams change sides (and places in the packet), the other team kicks off. */
	void SwitchHalf() {
		packet.firstHalf = 0;
		std::swap(packet.teams[0], packet.teams[1]);
		packet.state = gc::kStateInitial;
		packet.kickingTeam = kAway;
		packet.secsRemaining = 600;
		packet.secondaryTime = 0;
	}
	void StartPenaltyShootOut() {
		packet.gamePhase = gc::kGamePhasePenaltyShoot;
		packet.state = gc::kStateInitial;
		packet.kickingTeam = kHome;
		packet.secsRemaining = 0;
		packet.secondaryTime = 0;
		for (auto& team : packet.teams) {
			team.penaltyShot = 0;
			for (auto& player : team.players) player = {gc::kPenaltySubstitute, 0};
		}
	}
	/** "Set" of the next penalty shot: after a shot everyone is a substitute again and the other team shoots. */
	void WaitForPenaltyShot() {
		if (packet.state == gc::kStateFinished) {
			for (auto& team : packet.teams) {
				for (auto& player : team.players) player = {gc::kPenaltySubstitute, 0};
			}
			std::swap(packet.teams[0], packet.teams[1]);
			packet.kickingTeam = packet.kickingTeam == kHome ? kAway : kHome;
		}
		packet.state = gc::kStateSet;
		packet.secsRemaining = 30;
		++Team(packet.kickingTeam).penaltyShot;
	}
	void SelectPenaltyShotPlayer(int team, int number) { Team(team).players[static_cast<std::size_t>(number - 1)] = {gc::kPenaltyNone, 0}; }
};

MatchConfig FourChasers() {
	MatchConfig config;
	config.seed = 13;
	config.home.number = kHome;
	config.away.number = kAway;
	for (int n = 1; n <= 2; ++n) {
		config.home.players.push_back({"Chaser", n, std::nullopt, {}});
		config.away.players.push_back({"Chaser", n, std::nullopt, {}});
	}
	return config;
}

/** A match listening to a link on loopback, and GameController3's socket that sends to it. */
class LoopbackGame {
public:
	explicit LoopbackGame(MatchConfig config = FourChasers()) : link_({"127.0.0.1", 0, controller_.Port()}), match_(std::move(config)) {
		match_.Listen(link_);
	}

	Match& GetMatch() { return match_; }
	const gc::GameControllerLink& Link() const { return link_; }

	/** Sends the packet {@code copies} times, 0.5 s of match time apart, from GameController3's socket or another. */
	void Send(gc::GameControlData packet, int copies = 1, const UdpSender* from = nullptr) {
		for (int i = 0; i < copies; ++i) {
			packet.packetNumber = packet_number_++;
			const std::uint64_t before = link_.Stats().received;
			ASSERT_TRUE((from ? *from : controller_).SendTo(link_.ListenPort(), gc::Encode(packet)));
			const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
			for (;;) {
				ASSERT_LT(std::chrono::steady_clock::now(), deadline) << "the link never received the packet";
				match_.Step();
				if (link_.Stats().received != before) break;
				std::this_thread::sleep_for(std::chrono::microseconds(200));
			}
			// the next packet 0.5 s after this one arrived: a late arrival only makes the wait longer
			for (int tick = 1; tick < kTicksPerPacket; ++tick) match_.Step();
			answers_ += controller_.Drain();
		}
	}

	std::vector<std::string> Details(const std::string& type) const {
		std::vector<std::string> details;
		for (const auto& event : match_.Events()) {
			if (event.type == type) details.push_back(event.detail);
		}
		return details;
	}
	int Answers() const { return answers_; }

private:
	UdpSender controller_;
	gc::GameControllerLink link_;
	Match match_;
	std::uint8_t packet_number_ = 0;
	int answers_ = 0;
};

using States = std::vector<std::string>;

}  // namespace

TEST(GameControllerGame, AForgedFinishedPacketDoesNotEndTheMatch) {
	LoopbackGame game;
	GameController3 controller;
	controller.SwitchHalf();
	controller.State(gc::kStatePlaying);
	controller.packet.secsRemaining = 300;
	game.Send(controller.packet, 4);

	gc::GameControlData forged = controller.packet;
	forged.state = gc::kStateFinished;
	forged.secsRemaining = 0;
	const UdpSender forger;
	game.Send(forged, 1, &forger);
	EXPECT_EQ(game.GetMatch().GetReferee().State(), GameState::Finished) << "a state in a packet is a state the robots follow";
	EXPECT_FALSE(game.GetMatch().GetReferee().GameOver()) << "but not an exit";
	const double forged_at = game.GetMatch().Time();
	game.GetMatch().Run(0.2);
	EXPECT_NEAR(game.GetMatch().Time() - forged_at, 0.2, 1e-9);
	game.Send(controller.packet, 1);
	EXPECT_EQ(game.GetMatch().GetReferee().State(), GameState::Playing) << "and the next packet's state, too";
	game.Send(forged, 3, &forger);  // even several in a row, between two of GameController3's
	game.Send(controller.packet, 20);
	EXPECT_FALSE(game.GetMatch().GetReferee().GameOver());

	const double before = game.GetMatch().Time();
	game.GetMatch().Run(1.0);
	EXPECT_NEAR(game.GetMatch().Time() - before, 1.0, 1e-9) << "the match goes on";
	EXPECT_EQ(game.GetMatch().GetReferee().State(), GameState::Playing);
	EXPECT_EQ(game.Details("state"), (States{"INITIAL", "PLAYING", "FINISHED", "PLAYING", "FINISHED", "PLAYING"}));
}

TEST(GameControllerGame, TheMatchFollowsBothHalvesAndEndsWhenTheGameIsOver) {
	LoopbackGame game;
	Match& match = game.GetMatch();
	GameController3 controller;
	game.Send(controller.packet, 2);
	EXPECT_EQ(match.GetReferee().State(), GameState::Initial);
	EXPECT_TRUE(match.GetReferee().Following());
	for (const std::uint8_t state : {gc::kStateReady, gc::kStateSet, gc::kStatePlaying}) {
		controller.State(state);
		game.Send(controller.packet, 2);
	}
	EXPECT_EQ(match.LastPerception(0).player_state, 3);
	EXPECT_TRUE(match.LastPerception(0).kickoff);
	controller.packet.secsRemaining = 0;
	controller.State(gc::kStateFinished);
	controller.packet.secondaryTime = 600;  // the half-time break
	game.Send(controller.packet, 12);
	EXPECT_EQ(match.GetReferee().State(), GameState::Finished);
	EXPECT_FALSE(match.GetReferee().GameOver()) << "FINISHED after the first half is half-time";
	const double before = match.Time();
	match.Run(1.0);
	EXPECT_NEAR(match.Time() - before, 1.0, 1e-9) << "kse-match keeps running at half-time";

	controller.SwitchHalf();
	game.Send(controller.packet, 2);
	EXPECT_EQ(match.GetReferee().Half(), 2);
	EXPECT_EQ(match.GetReferee().KickingTeam(), 1);
	EXPECT_EQ(match.GetReferee().Side(0), -1) << "the teams changed ends";
	for (const std::uint8_t state : {gc::kStateReady, gc::kStateSet, gc::kStatePlaying}) {
		controller.State(state);
		game.Send(controller.packet, 2);
	}
	controller.Team(kHome).score = 1;
	game.Send(controller.packet, 2);
	EXPECT_EQ(match.LastPerception(0).our_score, 1);
	EXPECT_EQ(match.LastPerception(2).their_score, 1);

	controller.State(gc::kStateFinished);
	controller.packet.secsRemaining = 0;
	game.Send(controller.packet, 1);
	EXPECT_EQ(match.GetReferee().State(), GameState::Finished);
	EXPECT_FALSE(match.GetReferee().GameOver()) << "never on one packet";
	game.Send(controller.packet, 7);  // 4 s
	EXPECT_FALSE(match.GetReferee().GameOver());
	game.Send(controller.packet, 2);  // 5 s: the default game_over_seconds
	EXPECT_TRUE(match.GetReferee().GameOver());
	const double over = match.Time();
	match.Run(60);
	EXPECT_EQ(match.Time(), over) << "Run stops when the game is over";

	EXPECT_EQ(game.Details("state"), (States{"INITIAL", "READY", "SET", "PLAYING", "FINISHED", "INITIAL", "READY", "SET", "PLAYING", "FINISHED"}));
	EXPECT_EQ(game.Details("half-time").size(), 1u);
	EXPECT_TRUE(game.Details("gamecontroller").empty()) << "nothing to say about GameController3's own packets";
	EXPECT_GE(game.Answers(), 100) << "every robot answered twice a second";
}

TEST(GameControllerGame, PenaltyShootOutIsFollowed) {
	MatchConfig config = FourChasers();
	config.referee.shoot_out_wait_seconds = 10;
	LoopbackGame game(config);
	Match& match = game.GetMatch();
	GameController3 controller;
	controller.SwitchHalf();
	controller.State(gc::kStatePlaying);
	controller.Team(kHome).score = 1;
	controller.Team(kAway).score = 1;
	game.Send(controller.packet, 2);
	controller.State(gc::kStateFinished);
	controller.packet.secsRemaining = 0;
	game.Send(controller.packet, 14);  // 7 s: more than game_over_seconds, less than the wait
	EXPECT_FALSE(match.GetReferee().GameOver()) << "a drawn play-off game may go to a shoot-out";

	controller.StartPenaltyShootOut();
	game.Send(controller.packet, 2);
	EXPECT_TRUE(match.GetReferee().PenaltyShootOut());
	EXPECT_EQ(match.GetReferee().Penalty(0), gc::kPenaltySubstitute);
	EXPECT_FALSE(match.GetWorld().bodies[0].on_field);

	// shot 1: home's player 2 against away's goalkeeper
	controller.WaitForPenaltyShot();
	game.Send(controller.packet, 2);
	EXPECT_EQ(match.GetReferee().State(), GameState::Set);
	const double end = match.GetReferee().Side(0);  // home shoots on the goal it attacks
	EXPECT_NEAR(match.GetWorld().ball.position.x, end * (4.5 - 1.3), 1e-9) << "the ball on the penalty mark";
	controller.SelectPenaltyShotPlayer(kHome, 2);
	controller.SelectPenaltyShotPlayer(kAway, 1);
	game.Send(controller.packet, 2);
	const Body& striker = match.GetWorld().bodies[1];
	const Body& keeper = match.GetWorld().bodies[2];
	EXPECT_TRUE(striker.on_field);
	EXPECT_TRUE(keeper.on_field);
	EXPECT_NEAR(keeper.pose.x, end * 4.5, 0.05) << "the goalkeeper on its goal line";
	EXPECT_LT(end * striker.pose.x, end * match.GetWorld().ball.position.x) << "the striker behind the ball";
	controller.State(gc::kStatePlaying);
	game.Send(controller.packet, 4);
	controller.State(gc::kStateFinished);
	controller.Team(kHome).score = 2;
	game.Send(controller.packet, 12);  // 6 s
	EXPECT_FALSE(match.GetReferee().GameOver()) << "the next shot may follow";

	// shot 2: away shoots
	controller.WaitForPenaltyShot();
	game.Send(controller.packet, 2);
	EXPECT_EQ(match.GetReferee().KickingTeam(), 1);
	controller.SelectPenaltyShotPlayer(kAway, 2);
	controller.SelectPenaltyShotPlayer(kHome, 1);
	controller.State(gc::kStatePlaying);
	game.Send(controller.packet, 4);
	controller.State(gc::kStateFinished);
	game.Send(controller.packet, 18);  // 9 s
	EXPECT_FALSE(match.GetReferee().GameOver());
	game.Send(controller.packet, 2);  // 10 s: shoot_out_wait_seconds
	EXPECT_TRUE(match.GetReferee().GameOver());
	EXPECT_EQ(match.GetReferee().Score()[0], 2);

	EXPECT_EQ(game.Details("penalty-shoot-out").size(), 1u);
	EXPECT_EQ(game.Details("state"),
	          (States{"INITIAL", "PLAYING", "FINISHED", "INITIAL", "SET", "PLAYING", "FINISHED", "SET", "PLAYING", "FINISHED"}));
}

TEST(GameControllerGame, UnknownTeamNumbersAreReportedAtOnce) {
	LoopbackGame game;
	Match& match = game.GetMatch();
	GameController3 controller;
	controller.packet.teams[0].teamNumber = 5;
	controller.packet.teams[1].teamNumber = 12;
	controller.packet.kickingTeam = 5;
	controller.State(gc::kStateReady);
	game.Send(controller.packet, 1);
	auto notices = game.Details("gamecontroller");
	ASSERT_EQ(notices.size(), 1u) << "said with the first packet";
	EXPECT_EQ(notices[0],
	          "the GameController's packets are for teams 5 and 12, not for ours (home 7, away 8): the robots wait until packets name them "
	          "(kse-match --home-number, --away-number)");
	game.Send(controller.packet, 20);
	EXPECT_EQ(game.Details("gamecontroller").size(), 1u) << "and only once";
	EXPECT_EQ(match.GetReferee().State(), GameState::Initial) << "kse-match does not play its own referee meanwhile";
	EXPECT_FALSE(match.GetReferee().Following());

	controller.packet.teams[0].teamNumber = kHome;  // the operator sets one of our numbers
	controller.packet.kickingTeam = kHome;
	game.Send(controller.packet, 4);
	notices = game.Details("gamecontroller");
	ASSERT_EQ(notices.size(), 2u);
	EXPECT_EQ(notices[1],
	          "team 8 (away) is not in the GameController's packets (teams 7 and 12): its robots follow the game but get no score or "
	          "penalties (kse-match --away-number 12 names it)");
	EXPECT_EQ(match.GetReferee().State(), GameState::Ready);
}

TEST(GameControllerGame, OutOfRangePenaltyAndTimesAreBoundedAndLoggedOnce) {
	LoopbackGame game;
	Match& match = game.GetMatch();
	GameController3 controller;
	controller.State(gc::kStatePlaying);
	controller.packet.secsRemaining = -5;
	controller.packet.secondaryTime = 32767;
	controller.Team(kHome).players[1] = {250, 44};
	game.Send(controller.packet, 6);
	EXPECT_EQ(match.GetReferee().SecsRemaining(), 0);
	EXPECT_EQ(match.GetReferee().SecondaryTime(), Referee::kLongestTime);
	EXPECT_EQ(match.LastPerception(0).secs_remaining, 0) << "robots are never told a negative time";
	EXPECT_EQ(match.GetReferee().Penalty(1), gc::kPenaltyManual) << "an unknown penalty is a penalty, but one of the protocol";
	EXPECT_FALSE(match.GetWorld().bodies[1].on_field);
	controller.packet.state = 9;
	game.Send(controller.packet, 6);
	EXPECT_EQ(match.GetReferee().State(), GameState::Playing) << "a state outside the protocol changes nothing";

	EXPECT_EQ(game.Details("gamecontroller"), (States{
	                                              "secsRemaining -5 is outside 0 to 3600 s: the robots are told 0",
	                                              "secondaryTime 32767 is outside 0 to 3600 s: the robots are told 3600",
	                                              "penalty 250 is not a GameController penalty: taken as 15 (manual)",
	                                              "state 9 is not a GameController state: the robots keep PLAYING",
	                                          }));
	for (const auto& event : match.Events()) {
		if (event.type == "gamecontroller" && event.detail.rfind("penalty", 0) == 0) EXPECT_EQ(event.robot, 1) << "the log names the robot";
	}
}

TEST(GameControllerGame, IgnoredPacketsAreLoggedOncePerKind) {
	LoopbackGame game;
	GameController3 controller;
	auto bytes = gc::Encode(controller.packet);
	auto wrong_header = bytes;
	wrong_header[0] = 'X';
	auto wrong_version = bytes;
	wrong_version[4] = 17;
	std::vector<std::uint8_t> too_short(bytes.begin(), bytes.begin() + 40);
	auto too_long = bytes;
	too_long.resize(3000);
	const UdpSender sender;
	for (int i = 0; i < 5; ++i) {
		for (const auto* datagram : {&wrong_header, &wrong_version, &too_short, &too_long}) ASSERT_TRUE(sender.SendTo(game.Link().ListenPort(), *datagram));
	}
	game.Send(controller.packet, 2);  // behind them in the queue
	EXPECT_EQ(game.Link().Malformed(), 20u);
	EXPECT_EQ(game.Details("gamecontroller"), (States{
	                                              "ignored a packet with the header 'XGme', not 'RGme'; further ones are only counted",
	                                              "ignored a version 17 packet: kse-match follows version 18 (GameController3); further ones are only counted",
	                                              "ignored a 40-byte packet: too short for version 18 (118 bytes); further ones are only counted",
	                                              "ignored a 3000-byte packet: too long for version 18 (118 bytes); further ones are only counted",
	                                          }));
}

TEST(GameControllerGame, ASilentGameControllerIsReportedOncePerSilence) {
	MatchConfig config = FourChasers();
	config.referee.silence_seconds = 2;
	LoopbackGame game(config);
	Match& match = game.GetMatch();
	match.Run(6);
	EXPECT_EQ(game.Details("gamecontroller"), (States{"no packet from a GameController in 2 s: is one running and sending to this machine?"}));
	EXPECT_EQ(match.GetReferee().State(), GameState::Initial);
	GameController3 controller;
	controller.State(gc::kStatePlaying);
	game.Send(controller.packet, 2);
	match.Run(6);
	EXPECT_EQ(game.Details("gamecontroller").size(), 2u);
	EXPECT_EQ(game.Details("gamecontroller").back(), "no packet from the GameController for 2 s: the robots keep PLAYING");
}

TEST(GameControllerGame, KseMatchFollowsAGameControllerThatSendsInRealTime) {
	// as kse-match --gamecontroller runs: Run in real time, GameController3 on its own thread sending twice a second
	MatchConfig config = FourChasers();
	config.referee.game_over_seconds = 1;
	UdpSender controller;
	gc::GameControllerLink link({"127.0.0.1", 0, controller.Port()});
	Match match(config);
	match.Listen(link);
	std::atomic<bool> stop{false};
	std::thread sender([&] {
		GameController3 game;
		std::vector<gc::GameControlData> script;
		for (const std::uint8_t state : {gc::kStateInitial, gc::kStateReady, gc::kStateSet, gc::kStatePlaying, gc::kStateFinished}) {
			game.State(state);
			script.push_back(game.packet);
		}
		game.SwitchHalf();
		script.push_back(game.packet);
		game.State(gc::kStatePlaying);
		script.push_back(game.packet);
		game.Team(kHome).score = 1;  // a decided game: no shoot-out to wait for
		game.State(gc::kStateFinished);
		for (std::uint8_t number = 0; !stop; ++number) {
			gc::GameControlData packet = number < script.size() ? script[number] : game.packet;
			packet.packetNumber = number;
			controller.SendTo(link.ListenPort(), gc::Encode(packet));  // a lost datagram is what the link must bear
			for (int wait = 0; wait < 50 && !stop; ++wait) std::this_thread::sleep_for(std::chrono::milliseconds(10));
		}
	});
	const auto started = std::chrono::steady_clock::now();
	match.Run(60, {}, true);
	const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
	stop = true;
	sender.join();
	EXPECT_TRUE(match.GetReferee().GameOver()) << "Run ended by itself, not after its 60 s";
	EXPECT_LT(wall, 30);
	EXPECT_GE(match.Time(), 7 * 0.5 + 1 - 0.5) << "seven packets and the FINISHED held for a second";
	EXPECT_EQ(match.GetReferee().Half(), 2);
	std::vector<std::string> states;
	for (const auto& event : match.Events()) {
		if (event.type == "state") states.push_back(event.detail);
	}
	EXPECT_EQ(states, (States{"INITIAL", "READY", "SET", "PLAYING", "FINISHED", "INITIAL", "PLAYING", "FINISHED"}));
}
