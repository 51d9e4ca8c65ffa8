#include <kse/sim/GameControllerLink.h>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace kse::sim::gc {

namespace {

sockaddr_in Address(const std::string& address, std::uint16_t port) {
	sockaddr_in result{};
	result.sin_family = AF_INET;
	result.sin_port = htons(port);
	if (inet_pton(AF_INET, address.c_str(), &result.sin_addr) != 1) {
		throw std::runtime_error("GameController link: '" + address + "' is not an IPv4 address");
	}
	return result;
}

std::runtime_error SocketError(const std::string& what, const std::string& address, std::uint16_t port) {
	return std::runtime_error("GameController link: cannot " + what + " " + address + ":" + std::to_string(port) + ": " + std::strerror(errno));
}

}  // namespace

GameControllerLink::GameControllerLink(Options options) : options_(std::move(options)) {
	const sockaddr_in local = Address(options_.address, options_.listen_port);
	receive_socket_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
	if (receive_socket_ < 0) throw SocketError("open a socket for", options_.address, options_.listen_port);
	// several robots (processes) on one machine listen to the same GameController
	const int yes = 1;
	::setsockopt(receive_socket_, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
	if (::bind(receive_socket_, reinterpret_cast<const sockaddr*>(&local), sizeof local) != 0) {
		const auto error = SocketError("listen on", options_.address, options_.listen_port);
		::close(receive_socket_);
		throw error;
	}
	sockaddr_in bound{};
	socklen_t length = sizeof bound;
	::getsockname(receive_socket_, reinterpret_cast<sockaddr*>(&bound), &length);
	listen_port_ = ntohs(bound.sin_port);
	send_socket_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
	if (send_socket_ < 0) {
		const auto error = SocketError("open a socket to answer", options_.address, options_.return_port);
		::close(receive_socket_);
		throw error;
	}
}

GameControllerLink::~GameControllerLink() {
	if (receive_socket_ >= 0) ::close(receive_socket_);
	if (send_socket_ >= 0) ::close(send_socket_);
}

std::vector<GameControlData> GameControllerLink::Receive() {
	std::vector<GameControlData> packets;
	std::uint8_t buffer[2048];
	for (;;) {
		// MSG_TRUNC: the datagram's real length, so an oversized one is never taken for a valid one
		const ssize_t size = ::recv(receive_socket_, buffer, sizeof buffer, MSG_TRUNC);
		if (size < 0) break;  // EAGAIN: nothing more waiting (other errors: try again next tick)
		const auto length = static_cast<std::size_t>(size);
		if (auto packet = Accept(buffer, length, length > sizeof buffer)) packets.push_back(*packet);
	}
	return packets;
}

std::optional<GameControlData> GameControllerLink::Poll() {
	auto packets = Receive();
	if (packets.empty()) return std::nullopt;
	return packets.back();
}

std::vector<std::string> GameControllerLink::TakeNotices() {
	std::vector<std::string> taken;
	taken.swap(notices_);
	return taken;
}

std::optional<GameControlData> GameControllerLink::Accept(const std::uint8_t* datagram, std::size_t size, bool truncated) {
	++stats_.received;
	PacketError error = PacketError::TooLong;
	auto packet = truncated ? std::nullopt : DecodeGameControlData(datagram, size, &error);
	std::uint64_t* count = nullptr;
	std::string what;
	switch (error) {
		case PacketError::None: ++stats_.accepted; return packet;
		case PacketError::TooShort:
			count = &stats_.too_short;
			what = "a " + std::to_string(size) + "-byte packet: too short for version " + std::to_string(kVersion) + " (" + std::to_string(kPacketSize) + " bytes)";
			break;
		case PacketError::TooLong:
			count = &stats_.too_long;
			what = "a " + std::to_string(size) + "-byte packet: too long for version " + std::to_string(kVersion) + " (" + std::to_string(kPacketSize) + " bytes)";
			break;
		case PacketError::WrongHeader: {
			count = &stats_.wrong_header;
			std::string header;
			for (std::size_t i = 0; i < 4; ++i) header += datagram[i] >= 0x20 && datagram[i] < 0x7F ? static_cast<char>(datagram[i]) : '?';
			what = "a packet with the header '" + header + "', not 'RGme'";
			break;
		}
		case PacketError::WrongVersion:
			count = &stats_.wrong_version;
			what = "a version " + std::to_string(datagram[4]) + " packet: kse-match follows version " + std::to_string(kVersion) + " (GameController3)";
			break;
	}
	if ((*count)++ == 0) notices_.push_back("ignored " + what + "; further ones are only counted");
	return std::nullopt;
}

void GameControllerLink::SendReturn(const ReturnData& status) {
	const auto bytes = Encode(status);
	const sockaddr_in target = Address(options_.address, options_.return_port);
	const ssize_t sent = ::sendto(send_socket_, bytes.data(), bytes.size(), 0, reinterpret_cast<const sockaddr*>(&target), sizeof target);
	if (sent != static_cast<ssize_t>(bytes.size())) ++stats_.send_errors;
}

}  // namespace kse::sim::gc
