#pragma once
// The RoboCup SPL GameController protocol, version 18 (docs/original-kse.md §10): the 118-byte
// RoboCupGameControlData packets the GameController sends to UDP 3838 and the 32-byte status
// robots return to 3939. Encoded and decoded field by field, little-endian, whatever the host.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace kse::sim::gc {

constexpr std::uint16_t kGameControllerPort = 3838;
constexpr std::uint16_t kReturnPort = 3939;
constexpr char kHeader[4] = {'R', 'G', 'm', 'e'};
constexpr std::uint8_t kVersion = 18;
constexpr char kReturnHeader[4] = {'R', 'G', 'r', 't'};
constexpr std::uint8_t kReturnVersion = 4;
constexpr std::size_t kMaxPlayers = 20;
constexpr std::size_t kPacketSize = 118;
constexpr std::size_t kReturnSize = 32;

// state
constexpr std::uint8_t kStateInitial = 0, kStateReady = 1, kStateSet = 2, kStatePlaying = 3, kStateFinished = 4, kStateStandby = 5;
// setPlay
constexpr std::uint8_t kSetPlayNone = 0, kSetPlayGoalKick = 1, kSetPlayPushingFreeKick = 2, kSetPlayCornerKick = 3,
                       kSetPlayKickIn = 4, kSetPlayPenaltyKick = 5;
// gamePhase
constexpr std::uint8_t kGamePhaseNormal = 0, kGamePhasePenaltyShoot = 1, kGamePhaseOvertime = 2, kGamePhaseTimeout = 3;
// RobotInfo::penalty
constexpr std::uint8_t kPenaltyNone = 0, kPenaltyIllegalBallContact = 1, kPenaltyPlayerPushing = 2, kPenaltyIllegalMotionInSet = 3,
                       kPenaltyInactivePlayer = 4, kPenaltyIllegalPosition = 5, kPenaltyLeavingTheField = 6,
                       kPenaltyRequestForPickup = 7, kPenaltyLocalGameStuck = 8, kPenaltyIllegalPositionInSet = 9,
                       kPenaltyPlayerStance = 10, kPenaltyIllegalMotionInStandby = 11, kPenaltySubstitute = 14, kPenaltyManual = 15;
// kickingTeam when no team kicks off
constexpr std::uint8_t kKickingTeamNone = 255;

/** A penalty number of the protocol (12 and 13 are not). */
constexpr bool IsPenalty(std::uint8_t penalty) {
	return penalty <= kPenaltyIllegalMotionInStandby || penalty == kPenaltySubstitute || penalty == kPenaltyManual;
}

struct RobotInfo {
	std::uint8_t penalty = 0;
	std::uint8_t secsTillUnpenalised = 0;
	bool operator==(const RobotInfo& o) const { return penalty == o.penalty && secsTillUnpenalised == o.secsTillUnpenalised; }
};

struct TeamInfo {
	std::uint8_t teamNumber = 0;
	std::uint8_t fieldPlayerColour = 0;
	std::uint8_t goalkeeperColour = 0;
	std::uint8_t goalkeeper = 0;
	std::uint8_t score = 0;
	std::uint8_t penaltyShot = 0;
	std::uint16_t singleShots = 0;
	std::uint16_t messageBudget = 0;
	std::array<RobotInfo, kMaxPlayers> players{};
	bool operator==(const TeamInfo& o) const;
};

struct GameControlData {
	std::uint8_t packetNumber = 0;
	std::uint8_t playersPerTeam = 0;
	std::uint8_t competitionPhase = 0;
	std::uint8_t competitionType = 0;
	std::uint8_t gamePhase = 0;
	std::uint8_t state = 0;
	std::uint8_t setPlay = 0;
	std::uint8_t firstHalf = 0;
	std::uint8_t kickingTeam = 0;
	std::int16_t secsRemaining = 0;
	std::int16_t secondaryTime = 0;
	std::array<TeamInfo, 2> teams{};
	bool operator==(const GameControlData& o) const;
};

struct ReturnData {
	std::uint8_t playerNum = 0;
	std::uint8_t teamNum = 0;
	std::uint8_t fallen = 0;
	std::array<float, 3> pose{};  // x, y (mm), theta (rad)
	float ballAge = -1;            // s since the ball was seen, -1 never
	std::array<float, 2> ball{};   // relative position (mm)
	bool operator==(const ReturnData& o) const;
};

enum class PacketError { None, TooShort, WrongHeader, WrongVersion, TooLong };
const char* Describe(PacketError error);

std::vector<std::uint8_t> Encode(const GameControlData& data);
std::vector<std::uint8_t> Encode(const ReturnData& data);
/** Never throws and never reads beyond {@code size}; nullopt with the reason for a packet that is not a v18 one. */
std::optional<GameControlData> DecodeGameControlData(const std::uint8_t* data, std::size_t size, PacketError* error = nullptr);
std::optional<ReturnData> DecodeReturnData(const std::uint8_t* data, std::size_t size, PacketError* error = nullptr);

/** The team with this number, or nullptr when it does not play in this game. */
const TeamInfo* FindTeam(const GameControlData& data, std::uint8_t team_number);

}  // namespace kse::sim::gc
