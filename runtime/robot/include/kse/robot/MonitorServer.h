#pragma once
// The live monitor's endpoint (docs/monitor.md, ADR 0033): a loopback TCP port speaking JSON
// lines, guarded by a per-session token, that streams what robots' statecharts do to whoever
// subscribed to them. Any program using kse::robot can open one; kse-match does with --monitor.
//
// It runs on the caller's thread: sockets are non-blocking and Pump() does all the I/O, so a
// program's loop calls it once a cycle and nothing else runs behind its back. Sending only
// appends to a client's buffer; a client that does not read loses its connection, never the
// program its time.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <kse/messaging/MessageHub.h>
#include <statechart_engine/Statechart.h>

namespace kse::robot {

class MonitorServer {
public:
	struct Options {
		/** 0: a port the system chooses. Always on 127.0.0.1. */
		std::uint16_t port = 0;
		/** A client line longer than this (without its '\n') closes that client. */
		std::size_t max_line = 4096;
		/** What may wait unsent for one client; a client that lets more pile up is closed. */
		std::size_t max_outbound = std::size_t{8} << 20;
		/** From its connection, a client has this long to send a valid hello. */
		std::chrono::milliseconds hello_timeout{5000};
		/** SO_SNDBUF of a client's socket (0: the system's, which grows to megabytes on its own). */
		int kernel_send_buffer = 0;
		/** How long Finish() gives clients to take the last lines and close. */
		std::chrono::milliseconds finish_limit{3000};
		/** Clients at once; one more is closed as soon as it is accepted. */
		std::size_t max_clients = 16;
		/** Where a line about a client that was closed goes (standard error, "monitor: ...", when empty). */
		std::function<void(const std::string&)> notice;
	};

	/** What happened to clients so far. */
	struct Stats {
		std::size_t accepted = 0;
		std::size_t greeted = 0;      // sent a good hello
		std::size_t refused = 0;      // closed for a wrong token, a bad line, no hello in time, too many clients
		std::size_t overflowed = 0;   // closed because they did not read
	};

	/**
	 * Listens on 127.0.0.1 with a new token (32 bytes of getrandom, base64url). {@code robots}
	 * are the ids clients may subscribe to, in the order Send() numbers them. Throws
	 * std::runtime_error when it cannot listen or draw the token.
	 */
	MonitorServer(std::vector<std::string> robots, Options options);
	explicit MonitorServer(std::vector<std::string> robots) : MonitorServer(std::move(robots), Options{}) {}
	~MonitorServer();
	MonitorServer(const MonitorServer&) = delete;
	MonitorServer& operator=(const MonitorServer&) = delete;

	std::uint16_t Port() const noexcept { return port_; }
	const std::string& Token() const noexcept { return token_; }
	/** "monitor on 127.0.0.1:PORT token TOKEN": what a program prints so a relay can connect. */
	std::string Address() const;

	/** The first line every client gets after its hello (without '\n'), e.g. kse-match's "match" record. */
	void SetWelcome(std::string line);
	/**
	 * Called from Pump() for each robot a subscribe adds for a client: answer with SendTo() (the
	 * robot's configuration now), so a client is right from its first line on.
	 */
	void OnSubscribed(std::function<void(std::size_t client, std::size_t robot)> handler);
	/**
	 * Called from Pump() when a client asks for a robot's blackboard: answer with SendTo() (a
	 * "blackboard" record, BlackboardRecord()). Without a handler the client is told there is none.
	 * More than 10 requests in a second close that client.
	 */
	void OnBlackboard(std::function<void(std::size_t client, std::size_t robot)> handler);

	/** Accepts, reads and handles client lines, writes what is buffered. Never blocks. */
	void Pump();
	/** Whether some client is subscribed to {@code robot}: records need not be made otherwise. */
	bool Wants(std::size_t robot) const noexcept;
	/** Whether any client has sent a subscribe (for a program that waits for its first watcher). */
	bool AnySubscribed() const noexcept;
	/** How many clients connected now have sent a subscribe (for a program that waits for N watchers). */
	std::size_t Subscribers() const;
	/** One line (without '\n') for the clients subscribed to {@code robot}. */
	void Send(std::size_t robot, std::string_view line);
	/** One line for every client past its hello. */
	void SendAll(std::string_view line);
	/** One line for one client (the id OnSubscribed() gave). */
	void SendTo(std::size_t client, std::string_view line);
	/**
	 * The end: writes what is buffered (for at most {@code limit}), closes the clients' sending
	 * side and waits (within the same limit) for them to close theirs, so none loses the last
	 * lines to a reset; then closes everything. Later calls do nothing.
	 */
	void Finish(std::chrono::milliseconds limit);
	/** Finish() within Options::finish_limit. */
	void Finish() { Finish(options_.finish_limit); }

	Stats GetStats() const;
	std::size_t Clients() const;

private:
	struct Client;
	enum class Verdict { Keep, Close };

	void Accept();
	void Read(Client& client);
	Verdict Handle(Client& client, std::string_view line);
	void Write(Client& client);
	void Queue(Client& client, std::string_view line);
	void Drop(Client& client, const std::string& why, std::size_t Stats::*count);
	void Reap();
	void Notice(const std::string& line) const;

	std::vector<std::string> robots_;
	Options options_;
	int listener_ = -1;
	std::uint16_t port_ = 0;
	std::string token_;
	std::string welcome_;
	std::function<void(std::size_t, std::size_t)> on_subscribed_;
	std::function<void(std::size_t, std::size_t)> on_blackboard_;
	std::vector<std::unique_ptr<Client>> clients_;
	std::size_t next_id_ = 0;
	std::vector<std::size_t> watchers_;  // per robot: clients subscribed to it
	bool any_subscribed_ = false;
	bool finished_ = false;
	Stats stats_;
	// Everything is the caller's thread's, but a program's supervisor may end it from another
	// (Finish() after a hang): the lock keeps the two apart and costs nothing uncontended.
	mutable std::recursive_mutex mutex_;
};

/**
 * What a statechart's records need that does not change: each transition's index in its
 * Definition's Transitions() (model order: the diagram's //@transitions.N) by address, and the
 * states in document order. Made once per Definition and shared by its statecharts.
 */
class ChartIndex {
public:
	explicit ChartIndex(const statechart_engine::Definition& definition);
	/** Index of a transition of this definition, or -1. */
	long Of(const statechart_engine::TransitionSegmentBase& transition) const;
	std::size_t StateCount() const noexcept { return states_.size(); }
	std::size_t TransitionCount() const noexcept { return transitions_.size(); }
	/** Labels (State::Label()) of the active states of {@code chart}, root first, in document order, as a JSON array. */
	void AppendActive(std::string& out, const statechart_engine::Statechart& chart) const;

private:
	std::vector<const statechart_engine::State*> states_;
	std::unordered_map<const statechart_engine::TransitionSegmentBase*, long> transitions_;
};

/** Appends {@code text} as a JSON string literal. */
void AppendJsonString(std::string& out, std::string_view text);
/** Milliseconds since the Unix epoch now (system clock), the "wall" of a "taken" record. */
double WallMilliseconds();

/** {"type":"taken","t":..,"wall":..,"robot":..,"tr":..,"from":..,"to":..[,"expression":..]} (no '\n'). */
std::string TakenRecord(double t, double wall, std::string_view robot, long tr, const statechart_engine::TransitionSegmentBase& transition);
/** {"type":"active","t":..,"robot":..,"active":[labels]} (no '\n'). */
std::string ActiveRecord(double t, std::string_view robot, const ChartIndex& index, const statechart_engine::Statechart& chart);
/**
 * {"type":"blackboard","t":..,"robot":..,"states":[{"topic":..,"type":..,"age":s,"text":..}]}:
 * the State messages {@code hub} holds (what a blackboard subscribing now starts with), each in
 * protobuf's one-line text format, cut at 2 KiB (then "cut":true).
 */
std::string BlackboardRecord(double t, std::string_view robot, const messaging::MessageHub& hub);
/** {"type":"blackboard","robot":..,"error":..}: why a robot's blackboard cannot be shown. */
std::string BlackboardRefusal(std::string_view robot, std::string_view why);

namespace monitor_detail {
/** The two messages a client may send, read strictly; nullopt for anything else. */
struct ClientMessage {
	enum class Type { Hello, Subscribe, Blackboard } type = Type::Hello;
	std::string token;
	std::vector<std::string> robots;  // a blackboard request's robot is the one
};
std::optional<ClientMessage> ParseClientMessage(std::string_view line);
std::string Base64Url(const unsigned char* data, std::size_t size);
}  // namespace monitor_detail

}  // namespace kse::robot
