#include <kse/sim/GameControlData.h>

#include <cstring>

namespace kse::sim::gc {

namespace {

class Writer {
public:
	explicit Writer(std::size_t size) { bytes_.reserve(size); }
	void U8(std::uint8_t value) { bytes_.push_back(value); }
	void U16(std::uint16_t value) {
		U8(static_cast<std::uint8_t>(value & 0xFF));
		U8(static_cast<std::uint8_t>(value >> 8));
	}
	void I16(std::int16_t value) { U16(static_cast<std::uint16_t>(value)); }
	void F32(float value) {
		std::uint32_t bits = 0;
		std::memcpy(&bits, &value, sizeof bits);
		for (int shift = 0; shift < 32; shift += 8) U8(static_cast<std::uint8_t>((bits >> shift) & 0xFF));
	}
	void Header(const char (&header)[4]) {
		for (const char c : header) U8(static_cast<std::uint8_t>(c));
	}
	std::vector<std::uint8_t> Take() { return std::move(bytes_); }

private:
	std::vector<std::uint8_t> bytes_;
};

/** Reads a buffer whose size was checked before: every read is in bounds. */
class Reader {
public:
	explicit Reader(const std::uint8_t* data) : data_(data) {}
	std::uint8_t U8() { return data_[at_++]; }
	std::uint16_t U16() {
		const std::uint16_t low = U8();
		const std::uint16_t high = U8();
		return static_cast<std::uint16_t>(low | (high << 8));
	}
	std::int16_t I16() { return static_cast<std::int16_t>(U16()); }
	float F32() {
		std::uint32_t bits = 0;
		for (int shift = 0; shift < 32; shift += 8) bits |= static_cast<std::uint32_t>(U8()) << shift;
		float value = 0;
		std::memcpy(&value, &bits, sizeof value);
		return value;
	}

private:
	const std::uint8_t* data_;
	std::size_t at_ = 0;
};

PacketError Check(const std::uint8_t* data, std::size_t size, const char (&header)[4], std::uint8_t version, std::size_t expected) {
	if (data == nullptr || size < 5) return PacketError::TooShort;
	if (std::memcmp(data, header, 4) != 0) return PacketError::WrongHeader;
	if (data[4] != version) return PacketError::WrongVersion;
	if (size < expected) return PacketError::TooShort;
	if (size > expected) return PacketError::TooLong;
	return PacketError::None;
}

}  // namespace

bool TeamInfo::operator==(const TeamInfo& o) const {
	return teamNumber == o.teamNumber && fieldPlayerColour == o.fieldPlayerColour && goalkeeperColour == o.goalkeeperColour &&
	       goalkeeper == o.goalkeeper && score == o.score && penaltyShot == o.penaltyShot && singleShots == o.singleShots &&
	       messageBudget == o.messageBudget && players == o.players;
}

bool GameControlData::operator==(const GameControlData& o) const {
	return packetNumber == o.packetNumber && playersPerTeam == o.playersPerTeam && competitionPhase == o.competitionPhase &&
	       competitionType == o.competitionType && gamePhase == o.gamePhase && state == o.state && setPlay == o.setPlay &&
	       firstHalf == o.firstHalf && kickingTeam == o.kickingTeam && secsRemaining == o.secsRemaining &&
	       secondaryTime == o.secondaryTime && teams == o.teams;
}

bool ReturnData::operator==(const ReturnData& o) const {
	return playerNum == o.playerNum && teamNum == o.teamNum && fallen == o.fallen && pose == o.pose && ballAge == o.ballAge && ball == o.ball;
}

const char* Describe(PacketError error) {
	switch (error) {
		case PacketError::None: return "valid";
		case PacketError::TooShort: return "too short";
		case PacketError::WrongHeader: return "wrong header";
		case PacketError::WrongVersion: return "wrong version";
		case PacketError::TooLong: return "too long";
	}
	return "?";
}

std::vector<std::uint8_t> Encode(const GameControlData& data) {
	Writer out(kPacketSize);
	out.Header(kHeader);
	out.U8(kVersion);
	out.U8(data.packetNumber);
	out.U8(data.playersPerTeam);
	out.U8(data.competitionPhase);
	out.U8(data.competitionType);
	out.U8(data.gamePhase);
	out.U8(data.state);
	out.U8(data.setPlay);
	out.U8(data.firstHalf);
	out.U8(data.kickingTeam);
	out.I16(data.secsRemaining);
	out.I16(data.secondaryTime);
	for (const auto& team : data.teams) {
		out.U8(team.teamNumber);
		out.U8(team.fieldPlayerColour);
		out.U8(team.goalkeeperColour);
		out.U8(team.goalkeeper);
		out.U8(team.score);
		out.U8(team.penaltyShot);
		out.U16(team.singleShots);
		out.U16(team.messageBudget);
		for (const auto& player : team.players) {
			out.U8(player.penalty);
			out.U8(player.secsTillUnpenalised);
		}
	}
	return out.Take();
}

std::vector<std::uint8_t> Encode(const ReturnData& data) {
	Writer out(kReturnSize);
	out.Header(kReturnHeader);
	out.U8(kReturnVersion);
	out.U8(data.playerNum);
	out.U8(data.teamNum);
	out.U8(data.fallen);
	for (const float value : data.pose) out.F32(value);
	out.F32(data.ballAge);
	for (const float value : data.ball) out.F32(value);
	return out.Take();
}

std::optional<GameControlData> DecodeGameControlData(const std::uint8_t* bytes, std::size_t size, PacketError* error) {
	const PacketError problem = Check(bytes, size, kHeader, kVersion, kPacketSize);
	if (error) *error = problem;
	if (problem != PacketError::None) return std::nullopt;
	Reader in(bytes + 5);
	GameControlData data;
	data.packetNumber = in.U8();
	data.playersPerTeam = in.U8();
	data.competitionPhase = in.U8();
	data.competitionType = in.U8();
	data.gamePhase = in.U8();
	data.state = in.U8();
	data.setPlay = in.U8();
	data.firstHalf = in.U8();
	data.kickingTeam = in.U8();
	data.secsRemaining = in.I16();
	data.secondaryTime = in.I16();
	for (auto& team : data.teams) {
		team.teamNumber = in.U8();
		team.fieldPlayerColour = in.U8();
		team.goalkeeperColour = in.U8();
		team.goalkeeper = in.U8();
		team.score = in.U8();
		team.penaltyShot = in.U8();
		team.singleShots = in.U16();
		team.messageBudget = in.U16();
		for (auto& player : team.players) {
			player.penalty = in.U8();
			player.secsTillUnpenalised = in.U8();
		}
	}
	return data;
}

std::optional<ReturnData> DecodeReturnData(const std::uint8_t* bytes, std::size_t size, PacketError* error) {
	const PacketError problem = Check(bytes, size, kReturnHeader, kReturnVersion, kReturnSize);
	if (error) *error = problem;
	if (problem != PacketError::None) return std::nullopt;
	Reader in(bytes + 5);
	ReturnData data;
	data.playerNum = in.U8();
	data.teamNum = in.U8();
	data.fallen = in.U8();
	for (auto& value : data.pose) value = in.F32();
	data.ballAge = in.F32();
	for (auto& value : data.ball) value = in.F32();
	return data;
}

const TeamInfo* FindTeam(const GameControlData& data, std::uint8_t team_number) {
	for (const auto& team : data.teams) {
		if (team.teamNumber == team_number) return &team;
	}
	return nullptr;
}

}  // namespace kse::sim::gc
