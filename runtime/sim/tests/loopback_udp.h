// A UDP socket on loopback that plays GameController3 towards a link under test (or someone
// forging its packets), shared by the GameController tests.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>
#include <vector>

namespace kse::sim::test_support {

class LoopbackUdp {
public:
	LoopbackUdp() : fd_(::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0)) {
		sockaddr_in address{};
		address.sin_family = AF_INET;
		address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
		::bind(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address);
		socklen_t length = sizeof address;
		::getsockname(fd_, reinterpret_cast<sockaddr*>(&address), &length);
		port_ = ntohs(address.sin_port);
	}
	~LoopbackUdp() { ::close(fd_); }
	LoopbackUdp(const LoopbackUdp&) = delete;
	LoopbackUdp& operator=(const LoopbackUdp&) = delete;

	/** The port the link answers to (its "GameController port"). */
	std::uint16_t Port() const { return port_; }

	/** Sends one datagram to a port on loopback; false when it was not sent whole (errno says why). */
	bool SendTo(std::uint16_t port, const std::vector<std::uint8_t>& bytes) const {
		sockaddr_in to{};
		to.sin_family = AF_INET;
		to.sin_port = htons(port);
		to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
		return ::sendto(fd_, bytes.data(), bytes.size(), 0, reinterpret_cast<sockaddr*>(&to), sizeof to) == static_cast<ssize_t>(bytes.size());
	}

	/** Reads the robots' answers that are waiting, so that they never fill the socket; how many there were. */
	int Drain() const {
		int answers = 0;
		std::uint8_t buffer[256];
		while (::recv(fd_, buffer, sizeof buffer, MSG_DONTWAIT) > 0) ++answers;
		return answers;
	}

private:
	int fd_;
	std::uint16_t port_ = 0;
};

}  // namespace kse::sim::test_support
