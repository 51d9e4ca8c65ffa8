// A seeded fuzz of GameController packets (issue 13): random datagrams and hostile variants of
// GameController3's packets go over UDP on loopback through the link into a match, exactly as
// kse-match --gamecontroller takes them. It fails on a crash or a sanitizer report, on a link
// that judges a datagram otherwise than the decoder, on a match state out of its bounds, on any
// kind of ignored packet or out-of-range value logged more than once, and on a run over its
// time budget.
//
//   KSE_FUZZ_SEED=N     replays a run (the seed is printed first)
//   KSE_FUZZ_INPUTS=N   inputs per kind (default 1000)
//   KSE_FUZZ_BUDGET=S   seconds the whole run may take (default 120)
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <iterator>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include <kse/sim/GameControlData.h>
#include <kse/sim/GameControllerLink.h>
#include <kse/sim/Match.h>

#include "loopback_udp.h"
#include "test_behaviours.h"

using namespace kse::sim;
using Bytes = std::vector<std::uint8_t>;

namespace {

constexpr int kHome = 7, kAway = 8;
constexpr std::size_t kLargestDatagram = 65507;  // the most UDP carries over IPv4
constexpr std::size_t kLinkBuffer = 2048;        // what the link reads of a datagram

std::uint64_t FromEnvironment(const char* name, std::uint64_t otherwise) {
	const char* text = std::getenv(name);
	return text && *text ? std::strtoull(text, nullptr, 10) : otherwise;
}

enum class Kind { RandomBytes, WrongHeader, WrongVersion, Truncated, Oversized, FieldExtremes, ByteFlips };
constexpr Kind kKinds[] = {Kind::RandomBytes, Kind::WrongHeader, Kind::WrongVersion, Kind::Truncated,
                           Kind::Oversized,   Kind::FieldExtremes, Kind::ByteFlips};

const char* Name(Kind kind) {
	switch (kind) {
		case Kind::RandomBytes: return "random bytes";
		case Kind::WrongHeader: return "wrong header";
		case Kind::WrongVersion: return "wrong version";
		case Kind::Truncated: return "truncated";
		case Kind::Oversized: return "oversized";
		case Kind::FieldExtremes: return "fields at extremes";
		case Kind::ByteFlips: return "bytes flipped";
	}
	return "?";
}

/** Hostile datagrams, all from one seed. */
class Inputs {
public:
	explicit Inputs(std::uint64_t seed) : random_(seed) {}

	Bytes Make(Kind kind) {
		switch (kind) {
			case Kind::RandomBytes: {
				Bytes bytes(Length());
				for (auto& byte : bytes) byte = Byte();
				return bytes;
			}
			case Kind::WrongHeader: {
				Bytes bytes = Valid();
				do {
					bytes[Below(4)] = Byte();
				} while (std::memcmp(bytes.data(), gc::kHeader, 4) == 0);
				return bytes;
			}
			case Kind::WrongVersion: {
				Bytes bytes = Valid();
				do {
					bytes[4] = Byte();
				} while (bytes[4] == gc::kVersion);
				return bytes;
			}
			case Kind::Truncated: {
				Bytes bytes = Valid();
				bytes.resize(Below(gc::kPacketSize));
				return bytes;
			}
			case Kind::Oversized: {
				Bytes bytes = Valid();
				const std::size_t extra = Below(8) == 0 ? kLargestDatagram - gc::kPacketSize : 1 + Below(Below(2) ? 8 : 4000);
				for (std::size_t i = 0; i < extra; ++i) bytes.push_back(Byte());
				return bytes;
			}
			case Kind::FieldExtremes: {
				Bytes bytes = Valid();
				for (std::size_t n = 1 + Below(4); n > 0; --n) SetExtreme(bytes);
				return bytes;
			}
			case Kind::ByteFlips: {
				Bytes bytes = Valid();
				for (std::size_t n = 1 + Below(8); n > 0; --n) bytes[5 + Below(gc::kPacketSize - 5)] ^= static_cast<std::uint8_t>(1u << Below(8));
				return bytes;
			}
		}
		return {};
	}

private:
	std::size_t Below(std::size_t bound) { return static_cast<std::size_t>(random_() % bound); }
	std::uint8_t Byte() { return static_cast<std::uint8_t>(random_()); }
	std::size_t Length() {
		switch (Below(10)) {
			case 0: return gc::kPacketSize;
			case 1: return Below(kLargestDatagram + 1);
			case 2: return kLinkBuffer - 1 + Below(3);  // around the link's buffer
			default: return Below(300);
		}
	}

	/** A packet GameController3 could send for our game: a state, a half or the shoot-out, some penalties. */
	Bytes Valid() {
		gc::GameControlData packet;
		packet.playersPerTeam = 2;
		packet.competitionPhase = static_cast<std::uint8_t>(Below(2));
		packet.gamePhase = static_cast<std::uint8_t>(Below(4));
		packet.state = static_cast<std::uint8_t>(Below(6));
		packet.setPlay = static_cast<std::uint8_t>(Below(6));
		packet.firstHalf = static_cast<std::uint8_t>(Below(2));
		packet.kickingTeam = Below(2) ? kHome : kAway;
		packet.secsRemaining = static_cast<std::int16_t>(Below(601));
		packet.secondaryTime = static_cast<std::int16_t>(Below(46));
		packet.teams[0].teamNumber = kHome;
		packet.teams[1].teamNumber = kAway;
		if (Below(2)) std::swap(packet.teams[0].teamNumber, packet.teams[1].teamNumber);
		for (auto& team : packet.teams) {
			team.score = static_cast<std::uint8_t>(Below(10));
			team.goalkeeper = 1;
			for (std::size_t p = 0; p < 2; ++p) {
				if (Below(4) == 0) team.players[p] = {static_cast<std::uint8_t>(1 + Below(11)), static_cast<std::uint8_t>(Below(46))};
			}
		}
		return gc::Encode(packet);
	}

	/** One field of the packet (after header and version) set to its smallest, largest or any value. */
	void SetExtreme(Bytes& bytes) {
		struct Field {
			std::size_t at;
			std::size_t size;
		};
		static const std::vector<Field> fields = [] {
			std::vector<Field> list;
			for (std::size_t at = 5; at <= 13; ++at) list.push_back({at, 1});  // packetNumber … kickingTeam
			list.push_back({14, 2});                                        // secsRemaining
			list.push_back({16, 2});                                        // secondaryTime
			for (std::size_t team = 18; team < gc::kPacketSize; team += 50) {
				for (std::size_t at = 0; at < 6; ++at) list.push_back({team + at, 1});
				list.push_back({team + 6, 2});
				list.push_back({team + 8, 2});
				for (std::size_t player = 0; player < gc::kMaxPlayers; ++player) {
					list.push_back({team + 10 + 2 * player, 1});
					list.push_back({team + 11 + 2 * player, 1});
				}
			}
			return list;
		}();
		const Field field = fields[Below(fields.size())];
		const std::uint16_t value = Below(4) == 0 ? static_cast<std::uint16_t>(random_())
		                            : Below(3) == 0 ? 0
		                            : Below(2) == 0 ? 0xFFFF
		                                            : 0x8000;  // the most negative int16, or 0x00 in a byte
		bytes[field.at] = static_cast<std::uint8_t>(value & 0xFF);
		if (field.size == 2) bytes[field.at + 1] = static_cast<std::uint8_t>(value >> 8);
	}

	std::mt19937_64 random_;
};

/** What the link's statistics say about the last datagram. */
gc::PacketError Verdict(const gc::GameControllerLink::Statistics& before, const gc::GameControllerLink::Statistics& after) {
	if (after.too_short > before.too_short) return gc::PacketError::TooShort;
	if (after.wrong_header > before.wrong_header) return gc::PacketError::WrongHeader;
	if (after.wrong_version > before.wrong_version) return gc::PacketError::WrongVersion;
	if (after.too_long > before.too_long) return gc::PacketError::TooLong;
	return gc::PacketError::None;
}

/** The kind of a "gamecontroller" notice: each may be given once. */
std::string NoticeKind(const std::string& detail) {
	for (const char* prefix : {"ignored a packet with the header", "ignored a version", "the GameController's packets are for", "team 7 (home)",
	                           "team 8 (away)", "state ", "penalty ", "secsRemaining ", "secondaryTime ", "setPlay ", "gamePhase ",
	                           "firstHalf "}) {
		if (detail.rfind(prefix, 0) == 0) return prefix;
	}
	if (detail.rfind("ignored a ", 0) == 0 && detail.find("too short") != std::string::npos) return "too short";
	if (detail.rfind("ignored a ", 0) == 0 && detail.find("too long") != std::string::npos) return "too long";
	return "unexpected: " + detail;
}

void ExpectWithinBounds(const Match& match) {
	const Referee& referee = match.GetReferee();
	EXPECT_LE(static_cast<int>(referee.State()), static_cast<int>(GameState::Standby));
	EXPECT_TRUE(referee.Half() == 1 || referee.Half() == 2) << referee.Half();
	EXPECT_TRUE(referee.KickingTeam() >= -1 && referee.KickingTeam() <= 1) << referee.KickingTeam();
	EXPECT_TRUE(referee.SecsRemaining() >= 0 && referee.SecsRemaining() <= Referee::kLongestTime) << referee.SecsRemaining();
	EXPECT_TRUE(referee.SecondaryTime() >= 0 && referee.SecondaryTime() <= Referee::kLongestTime) << referee.SecondaryTime();
	EXPECT_LE(static_cast<int>(referee.CurrentSetPlay()), static_cast<int>(SetPlay::PenaltyKick));
	for (const int score : referee.Score()) EXPECT_TRUE(score >= 0 && score <= 255) << score;
	const World& world = match.GetWorld();
	EXPECT_TRUE(std::isfinite(world.ball.position.x) && std::fabs(world.ball.position.x) <= field::kCarpetHalfLength + 1);
	EXPECT_TRUE(std::isfinite(world.ball.position.y) && std::fabs(world.ball.position.y) <= field::kCarpetHalfWidth + 1);
	for (std::size_t i = 0; i < match.RobotCount(); ++i) {
		const int penalty = referee.Penalty(static_cast<int>(i));
		EXPECT_TRUE(penalty >= 0 && penalty <= 255 && gc::IsPenalty(static_cast<std::uint8_t>(penalty))) << penalty;
		const Pose2& pose = world.bodies[i].pose;
		EXPECT_TRUE(std::isfinite(pose.x) && std::fabs(pose.x) <= field::kCarpetHalfLength + 1) << pose.x;
		EXPECT_TRUE(std::isfinite(pose.y) && std::fabs(pose.y) <= field::kCarpetHalfWidth + 1) << pose.y;
		const auto& seen = match.LastPerception(i);
		EXPECT_TRUE(seen.game_state >= 0 && seen.game_state <= 5) << seen.game_state;
		EXPECT_TRUE(seen.player_state >= 0 && seen.player_state <= 5) << seen.player_state;
		EXPECT_TRUE(seen.secs_remaining >= 0 && seen.secs_remaining <= Referee::kLongestTime) << seen.secs_remaining;
	}
}

}  // namespace

TEST(GameControlFuzz, HostilePacketsNeitherCrashNorUnboundTheMatchNorFloodTheLog) {
	const std::uint64_t seed = FromEnvironment("KSE_FUZZ_SEED", 20261123);
	const std::uint64_t per_kind = FromEnvironment("KSE_FUZZ_INPUTS", 1000);
	const double budget = static_cast<double>(FromEnvironment("KSE_FUZZ_BUDGET", 120));
	std::cout << "GameController packet fuzz: seed " << seed << " (KSE_FUZZ_SEED=" << seed << " replays it), " << per_kind << " inputs per kind"
	          << std::endl;

	MatchConfig config;
	config.seed = seed;
	config.home.number = kHome;
	config.away.number = kAway;
	for (int n = 1; n <= 2; ++n) {
		config.home.players.push_back({"Chaser", n, std::nullopt, {}});
		config.away.players.push_back({"Chaser", n, std::nullopt, {}});
	}
	const test_support::LoopbackUdp controller;
	gc::GameControllerLink link({"127.0.0.1", 0, controller.Port()});
	Match match(config);
	match.Listen(link);
	Inputs inputs(seed);

	const auto started = std::chrono::steady_clock::now();
	auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
	std::map<Kind, std::uint64_t> accepted;
	std::uint64_t sent = 0;
	for (std::uint64_t round = 0; round < per_kind && !::testing::Test::HasFailure(); ++round) {
		for (const Kind kind : kKinds) {
			const Bytes bytes = inputs.Make(kind);
			SCOPED_TRACE("seed " + std::to_string(seed) + ", input " + std::to_string(sent) + " (" + Name(kind) + ", " + std::to_string(bytes.size()) +
			             " bytes)");
			// the decoder on an exact-size copy, so that AddressSanitizer sees any read beyond it
			const std::unique_ptr<std::uint8_t[]> exact(new std::uint8_t[bytes.size() + 1]);
			if (!bytes.empty()) std::memcpy(exact.get(), bytes.data(), bytes.size());
			gc::PacketError decoded = gc::PacketError::None;
			gc::DecodeGameControlData(exact.get(), bytes.size(), &decoded);
			if (bytes.size() > kLinkBuffer) decoded = gc::PacketError::TooLong;  // the link never reads its bytes

			const auto before = link.Stats();
			ASSERT_TRUE(controller.SendTo(link.ListenPort(), bytes)) << std::strerror(errno);
			++sent;
			const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
			do {
				match.Step();
				if (link.Stats().received == before.received) std::this_thread::sleep_for(std::chrono::microseconds(100));
			} while (link.Stats().received == before.received && std::chrono::steady_clock::now() < deadline);
			ASSERT_EQ(link.Stats().received, before.received + 1) << "the datagram never reached the link";
			EXPECT_EQ(Verdict(before, link.Stats()), decoded) << "the link judges a datagram as the decoder does";
			if (link.Stats().accepted > before.accepted) ++accepted[kind];
			ExpectWithinBounds(match);
			controller.Drain();
			if (::testing::Test::HasFailure()) break;
		}
		ASSERT_LT(elapsed(), budget) << "over the time budget after " << sent << " inputs";
	}

	std::map<std::string, int> notices;
	std::string said;
	for (const auto& event : match.Events()) {
		if (event.type != "gamecontroller") continue;
		++notices[NoticeKind(event.detail)];
		said += "    " + event.detail + "\n";
	}
	for (const auto& [kind, count] : notices) {
		EXPECT_EQ(kind.rfind("unexpected", 0), std::string::npos) << kind;
		EXPECT_EQ(count, 1) << "logged once, not per packet: " << kind;
	}
	const auto& stats = link.Stats();
	for (const auto& [kind, count] : {std::pair{"ignored a packet with the header", stats.wrong_header}, std::pair{"ignored a version", stats.wrong_version},
	                                  std::pair{"too short", stats.too_short}, std::pair{"too long", stats.too_long}}) {
		EXPECT_EQ(notices.count(kind), count > 0 ? 1u : 0u) << "every kind of ignored packet is said: " << kind;
	}
	if (per_kind >= 1000) {  // enough packets with extreme fields that each of these came
		for (const char* kind : {"penalty ", "secsRemaining ", "secondaryTime ", "state "}) {
			EXPECT_EQ(notices.count(kind), 1u) << "every out-of-range value is said: " << kind;
		}
	}
	EXPECT_GT(accepted[Kind::FieldExtremes], per_kind / 2) << "most packets with extreme fields reach the match";
	EXPECT_EQ(link.Stats().received, sent);
	std::cout << "  " << sent << " inputs (" << per_kind << " of each of " << std::size(kKinds) << " kinds), " << link.Stats().accepted
	          << " followed by the match, " << link.Malformed() << " ignored (" << link.Stats().too_short << " too short, " << link.Stats().too_long
	          << " too long, " << link.Stats().wrong_header << " wrong header, " << link.Stats().wrong_version << " wrong version), "
	          << notices.size() << " kinds of notice, in " << elapsed() << " s of a " << budget << " s budget; the log said:\n"
	          << said << std::flush;
}
