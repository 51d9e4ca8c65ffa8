#pragma once
// A loopback UDP link to a real GameController: receives its packets on 3838 (without blocking,
// malformed ones counted and ignored, the first of each kind described once) and sends the
// robots' status to 3939 without binding it, since the GameController binds 3939 itself.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <kse/sim/GameControlData.h>

namespace kse::sim::gc {

class GameControllerLink {
public:
	struct Options {
		std::string address = "127.0.0.1";
		std::uint16_t listen_port = kGameControllerPort;  // 0: any free port (tests)
		std::uint16_t return_port = kReturnPort;
	};

	struct Statistics {
		std::uint64_t received = 0;
		std::uint64_t accepted = 0;
		std::uint64_t too_short = 0;
		std::uint64_t wrong_header = 0;
		std::uint64_t wrong_version = 0;
		std::uint64_t too_long = 0;
		std::uint64_t send_errors = 0;
	};

	/** Binds address:listen_port; throws std::runtime_error naming both when that fails. */
	explicit GameControllerLink(Options options);
	~GameControllerLink();
	GameControllerLink(const GameControllerLink&) = delete;
	GameControllerLink& operator=(const GameControllerLink&) = delete;

	/** Reads every datagram waiting; the valid packets among them, oldest first. */
	std::vector<GameControlData> Receive();
	/** Reads every datagram waiting; the newest valid packet, or nullopt when none came. */
	std::optional<GameControlData> Poll();
	/** What the link ignored since the last call, the first datagram of each kind only: a GameController repeats itself twice a second. */
	std::vector<std::string> TakeNotices();
	/** Sends a robot's status to address:return_port; a failure is counted, never thrown. */
	void SendReturn(const ReturnData& status);

	std::uint16_t ListenPort() const { return listen_port_; }
	const Statistics& Stats() const { return stats_; }
	std::uint64_t Malformed() const { return stats_.too_short + stats_.wrong_header + stats_.wrong_version + stats_.too_long; }

private:
	/** The one way a datagram is judged; {@code truncated}: longer than the buffer it was read into. */
	std::optional<GameControlData> Accept(const std::uint8_t* datagram, std::size_t size, bool truncated);

	Options options_;
	int receive_socket_ = -1;
	int send_socket_ = -1;
	std::uint16_t listen_port_ = 0;
	Statistics stats_;
	std::vector<std::string> notices_;
};

}  // namespace kse::sim::gc
