// The GameController protocol v18: packets built byte by byte are read field by field,
// malformed ones are rejected with their reason and never crash, and the loopback link
// receives packets and answers with the robots' status.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include <kse/sim/GameControlData.h>
#include <kse/sim/GameControllerLink.h>

using namespace kse::sim::gc;
using Bytes = std::vector<std::uint8_t>;

namespace {

// A v18 packet written by hand at the offsets of the C struct: header 0, version 4,
// packetNumber 5, playersPerTeam 6, competitionPhase 7, competitionType 8, gamePhase 9, state 10,
// setPlay 11, firstHalf 12, kickingTeam 13, secsRemaining 14-15, secondaryTime 16-17,
// teams at 18 and 68 (50 bytes each: six bytes, singleShots, messageBudget, 20 x 2 bytes).
Bytes HandMadePacket(std::uint8_t state = 3) {
	Bytes b(118, 0);
	b[0] = 'R'; b[1] = 'G'; b[2] = 'm'; b[3] = 'e';
	b[4] = 18;
	b[5] = 201;  // packetNumber
	b[6] = 5;    // playersPerTeam
	b[7] = 1;    // competitionPhase
	b[8] = 0;    // competitionType
	b[9] = 0;    // gamePhase
	b[10] = state;
	b[11] = 4;   // setPlay kick-in
	b[12] = 1;   // firstHalf
	b[13] = 7;   // kickingTeam
	b[14] = 0xFB; b[15] = 0xFF;  // secsRemaining -5
	b[16] = 0x2C; b[17] = 0x01;  // secondaryTime 300
	b[18] = 7; b[19] = 1; b[20] = 2; b[21] = 1; b[22] = 3; b[23] = 0;  // team 7, colours, goalkeeper 1, score 3
	b[24] = 0x02; b[25] = 0x01;  // singleShots 0x0102
	b[26] = 0xB8; b[27] = 0x0B;  // messageBudget 3000
	b[28 + 2 * 2] = 6; b[28 + 2 * 2 + 1] = 44;  // player 3 left the field, 44 s to go
	b[68] = 8; b[72] = 1;  // team 8, score 1
	b[68 + 10 + 2 * 19] = 15; b[68 + 10 + 2 * 19 + 1] = 9;  // team 8, slot 20: manual penalty, 9 s
	return b;
}

GameControlData Filled() {
	GameControlData data;
	data.packetNumber = 9;
	data.playersPerTeam = 7;
	data.state = 2;
	data.setPlay = 3;
	data.firstHalf = 0;
	data.kickingTeam = 12;
	data.secsRemaining = -300;
	data.secondaryTime = 15;
	for (std::uint8_t t = 0; t < 2; ++t) {
		auto& team = data.teams[t];
		team.teamNumber = static_cast<std::uint8_t>(12 + t);
		team.score = static_cast<std::uint8_t>(4 - t);
		team.singleShots = static_cast<std::uint16_t>(0xABCD + t);
		team.messageBudget = 1200;
		for (std::uint8_t p = 0; p < kMaxPlayers; ++p) team.players[p] = {static_cast<std::uint8_t>(p % 16), static_cast<std::uint8_t>(p * 3 + t)};
	}
	return data;
}

int UdpSocket(std::uint16_t* port) {
	const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
	sockaddr_in address{};
	address.sin_family = AF_INET;
	address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
	::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address);
	socklen_t length = sizeof address;
	::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
	*port = ntohs(address.sin_port);
	return fd;
}

void SendTo(int fd, std::uint16_t port, const Bytes& bytes) {
	sockaddr_in address{};
	address.sin_family = AF_INET;
	address.sin_port = htons(port);
	address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
	ASSERT_EQ(::sendto(fd, bytes.data(), bytes.size(), 0, reinterpret_cast<sockaddr*>(&address), sizeof address),
	          static_cast<ssize_t>(bytes.size()));
}

}  // namespace

TEST(GameControlData, DecodesEveryFieldOfAHandMadePacket) {
	const Bytes bytes = HandMadePacket();
	PacketError error = PacketError::TooLong;
	const auto data = DecodeGameControlData(bytes.data(), bytes.size(), &error);
	ASSERT_TRUE(data.has_value());
	EXPECT_EQ(error, PacketError::None);
	EXPECT_EQ(data->packetNumber, 201);
	EXPECT_EQ(data->playersPerTeam, 5);
	EXPECT_EQ(data->competitionPhase, 1);
	EXPECT_EQ(data->state, kStatePlaying);
	EXPECT_EQ(data->setPlay, kSetPlayKickIn);
	EXPECT_EQ(data->firstHalf, 1);
	EXPECT_EQ(data->kickingTeam, 7);
	EXPECT_EQ(data->secsRemaining, -5);
	EXPECT_EQ(data->secondaryTime, 300);
	EXPECT_EQ(data->teams[0].teamNumber, 7);
	EXPECT_EQ(data->teams[0].fieldPlayerColour, 1);
	EXPECT_EQ(data->teams[0].goalkeeperColour, 2);
	EXPECT_EQ(data->teams[0].goalkeeper, 1);
	EXPECT_EQ(data->teams[0].score, 3);
	EXPECT_EQ(data->teams[0].singleShots, 0x0102);
	EXPECT_EQ(data->teams[0].messageBudget, 3000);
	EXPECT_EQ(data->teams[0].players[2].penalty, kPenaltyLeavingTheField);
	EXPECT_EQ(data->teams[0].players[2].secsTillUnpenalised, 44);
	EXPECT_EQ(data->teams[1].teamNumber, 8);
	EXPECT_EQ(data->teams[1].score, 1);
	EXPECT_EQ(data->teams[1].players[19].penalty, kPenaltyManual);
	EXPECT_EQ(data->teams[1].players[19].secsTillUnpenalised, 9);
	EXPECT_EQ(FindTeam(*data, 8), &data->teams[1]);
	EXPECT_EQ(FindTeam(*data, 9), nullptr);
	EXPECT_EQ(Encode(*data), bytes) << "encoding gives the same bytes back";
}

TEST(GameControlData, RoundTripsAndHasTheProtocolSizes) {
	const GameControlData data = Filled();
	const Bytes bytes = Encode(data);
	EXPECT_EQ(bytes.size(), kPacketSize);
	const auto back = DecodeGameControlData(bytes.data(), bytes.size());
	ASSERT_TRUE(back.has_value());
	EXPECT_EQ(*back, data);
}

TEST(GameControlData, RejectsMalformedPackets) {
	auto error_of = [](const Bytes& bytes) {
		PacketError error = PacketError::None;
		EXPECT_FALSE(DecodeGameControlData(bytes.data(), bytes.size(), &error).has_value());
		return error;
	};
	Bytes good = HandMadePacket();
	EXPECT_EQ(error_of({}), PacketError::TooShort);
	EXPECT_EQ(error_of(Bytes(good.begin(), good.end() - 1)), PacketError::TooShort);
	Bytes longer = good;
	longer.push_back(0);
	EXPECT_EQ(error_of(longer), PacketError::TooLong);
	Bytes header = good;
	header[3] = 'f';
	EXPECT_EQ(error_of(header), PacketError::WrongHeader);
	for (std::uint8_t version : {17, 19}) {
		Bytes old = good;
		old[4] = version;
		EXPECT_EQ(error_of(old), PacketError::WrongVersion);
	}
	EXPECT_FALSE(DecodeGameControlData(nullptr, 118).has_value());
	EXPECT_STREQ(Describe(PacketError::WrongVersion), "wrong version");
}

TEST(GameControlData, NeverCrashesOnGarbage) {
	std::mt19937 random(18);
	std::size_t accepted = 0;
	for (int i = 0; i < 10000; ++i) {
		const std::size_t size = random() % 300;
		Bytes bytes(size);
		for (auto& byte : bytes) byte = static_cast<std::uint8_t>(random());
		if (i % 2 == 0) {  // half of them start like a real packet
			const Bytes good = HandMadePacket();
			std::memcpy(bytes.data(), good.data(), std::min<std::size_t>(size, 5));
		}
		// an exact-size copy on the heap, so that AddressSanitizer sees any read beyond it
		std::unique_ptr<std::uint8_t[]> exact(new std::uint8_t[size + 1]);
		std::memcpy(exact.get(), bytes.data(), size);
		const auto data = DecodeGameControlData(exact.get(), size);
		accepted += data.has_value();
		EXPECT_EQ(data.has_value(), size == kPacketSize && i % 2 == 0);
		DecodeReturnData(exact.get(), size);
	}
	EXPECT_GT(accepted, 0u);
}

TEST(ReturnData, EncodesTheRobotStatusAsTheGameControllerReadsIt) {
	ReturnData status;
	status.playerNum = 3;
	status.teamNum = 7;
	status.fallen = 1;
	status.pose = {1.0f, -2.0f, 0.5f};
	status.ballAge = -1.0f;
	status.ball = {250.0f, 0.0f};
	const Bytes expected = {'R', 'G', 'r', 't', 4, 3, 7, 1,
	                        0x00, 0x00, 0x80, 0x3F,   // 1.0f
	                        0x00, 0x00, 0x00, 0xC0,   // -2.0f
	                        0x00, 0x00, 0x00, 0x3F,   // 0.5f
	                        0x00, 0x00, 0x80, 0xBF,   // -1.0f
	                        0x00, 0x00, 0x7A, 0x43,   // 250.0f
	                        0x00, 0x00, 0x00, 0x00};  // 0.0f
	EXPECT_EQ(Encode(status), expected);
	EXPECT_EQ(expected.size(), kReturnSize);
	const auto back = DecodeReturnData(expected.data(), expected.size());
	ASSERT_TRUE(back.has_value());
	EXPECT_EQ(*back, status);
}

TEST(GameControllerLink, ReceivesTheNewestValidPacketAndCountsTheRest) {
	std::uint16_t return_port = 0;
	const int receiver = UdpSocket(&return_port);
	GameControllerLink link({"127.0.0.1", 0, return_port});
	ASSERT_NE(link.ListenPort(), 0);
	std::uint16_t sender_port = 0;
	const int sender = UdpSocket(&sender_port);

	Bytes wrong_header = HandMadePacket();
	wrong_header[0] = 'X';
	Bytes old = HandMadePacket();
	old[4] = 17;
	SendTo(sender, link.ListenPort(), HandMadePacket(kStateReady));
	const Bytes good = HandMadePacket();
	SendTo(sender, link.ListenPort(), Bytes(good.begin(), good.begin() + 40));
	SendTo(sender, link.ListenPort(), wrong_header);
	SendTo(sender, link.ListenPort(), old);
	SendTo(sender, link.ListenPort(), Bytes(3000, 0));
	SendTo(sender, link.ListenPort(), HandMadePacket(kStateSet));

	std::optional<GameControlData> newest;
	const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
	while (link.Stats().received < 6 && std::chrono::steady_clock::now() < deadline) {
		if (auto packet = link.Poll()) newest = packet;
		std::this_thread::sleep_for(std::chrono::milliseconds(1));
	}
	ASSERT_TRUE(newest.has_value());
	EXPECT_EQ(newest->state, kStateSet) << "the newest valid packet wins";
	EXPECT_EQ(link.Stats().received, 6u);
	EXPECT_EQ(link.Stats().accepted, 2u);
	EXPECT_EQ(link.Stats().too_short, 1u);
	EXPECT_EQ(link.Stats().wrong_header, 1u);
	EXPECT_EQ(link.Stats().wrong_version, 1u);
	EXPECT_EQ(link.Stats().too_long, 1u);
	EXPECT_EQ(link.Malformed(), 4u);
	EXPECT_FALSE(link.Poll().has_value());

	ReturnData status;
	status.playerNum = 2;
	status.teamNum = 7;
	link.SendReturn(status);
	std::uint8_t buffer[256];
	ssize_t size = -1;
	const auto answer_deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
	while (size < 0 && std::chrono::steady_clock::now() < answer_deadline) {
		size = ::recv(receiver, buffer, sizeof buffer, MSG_DONTWAIT);
		if (size < 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
	}
	ASSERT_EQ(size, static_cast<ssize_t>(kReturnSize));
	EXPECT_EQ(Bytes(buffer, buffer + size), Encode(status));
	EXPECT_EQ(link.Stats().send_errors, 0u);
	::close(sender);
	::close(receiver);
}

TEST(GameControllerLink, SaysWhichAddressItCannotListenOn) {
	try {
		GameControllerLink link({"192.0.2.1", 3838, 3939});
		FAIL() << "bound an address that is not this machine's";
	} catch (const std::runtime_error& error) {
		EXPECT_NE(std::string(error.what()).find("192.0.2.1:3838"), std::string::npos) << error.what();
	}
	EXPECT_THROW(GameControllerLink({"localhost", 0, 3939}), std::runtime_error) << "an address, not a name";
}
