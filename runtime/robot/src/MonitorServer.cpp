#include <kse/robot/MonitorServer.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/random.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <deque>
#include <iostream>
#include <stdexcept>
#include <thread>

#include <google/protobuf/text_format.h>

namespace kse::robot {

// ---------------------------------------------------------------------------------------------
// The client's two messages. A general JSON library would accept far more than a client may
// say; this reader takes one object whose members are strings or arrays of strings, and
// nothing else, so every oddity ends in "closed" rather than in a half-understood message.

namespace monitor_detail {

namespace {

class Reader {
public:
	explicit Reader(std::string_view text) : text_(text) {}

	std::optional<ClientMessage> Message() {
		ClientMessage message;
		std::optional<std::string> type, token, robot;
		std::optional<std::vector<std::string>> robots;
		if (!Take('{')) return std::nullopt;
		Space();
		if (Peek() == '}') return std::nullopt;  // no "type"
		for (;;) {
			Space();
			auto key = String();
			if (!key || !Take(':')) return std::nullopt;
			Space();
			// each member once: a second "token" must not be able to override the first
			if (*key == "type" && !type) {
				type = String();
				if (!type) return std::nullopt;
			} else if (*key == "token" && !token) {
				token = String();
				if (!token) return std::nullopt;
			} else if (*key == "robots" && !robots) {
				robots = Strings();
				if (!robots) return std::nullopt;
			} else if (*key == "robot" && !robot) {
				robot = String();
				if (!robot) return std::nullopt;
			} else {
				return std::nullopt;
			}
			if (Take(',')) continue;
			if (Take('}')) break;
			return std::nullopt;
		}
		Space();
		if (at_ != text_.size()) return std::nullopt;
		if (type == "hello" && token && !robots && !robot) {
			message.type = ClientMessage::Type::Hello;
			message.token = std::move(*token);
			return message;
		}
		if (type == "subscribe" && robots && !token && !robot) {
			message.type = ClientMessage::Type::Subscribe;
			message.robots = std::move(*robots);
			return message;
		}
		if (type == "blackboard" && robot && !token && !robots) {
			message.type = ClientMessage::Type::Blackboard;
			message.robots = {std::move(*robot)};
			return message;
		}
		return std::nullopt;
	}

private:
	char Peek() const { return at_ < text_.size() ? text_[at_] : '\0'; }
	void Space() {
		while (at_ < text_.size() && (text_[at_] == ' ' || text_[at_] == '\t' || text_[at_] == '\r' || text_[at_] == '\n')) ++at_;
	}
	bool Take(char c) {
		Space();
		if (Peek() != c) return false;
		++at_;
		return true;
	}

	std::optional<std::vector<std::string>> Strings() {
		std::vector<std::string> values;
		if (!Take('[')) return std::nullopt;
		if (Take(']')) return values;
		for (;;) {
			Space();
			auto value = String();
			if (!value) return std::nullopt;
			values.push_back(std::move(*value));
			if (Take(',')) continue;
			if (Take(']')) return values;
			return std::nullopt;
		}
	}

	static bool Hex(char c, unsigned& value) {
		value <<= 4;
		if (c >= '0' && c <= '9') return value |= static_cast<unsigned>(c - '0'), true;
		if (c >= 'a' && c <= 'f') return value |= static_cast<unsigned>(c - 'a' + 10), true;
		if (c >= 'A' && c <= 'F') return value |= static_cast<unsigned>(c - 'A' + 10), true;
		return false;
	}
	bool Unit(unsigned& unit) {
		unit = 0;
		if (at_ + 4 > text_.size()) return false;
		for (int i = 0; i < 4; ++i) {
			if (!Hex(text_[at_++], unit)) return false;
		}
		return true;
	}
	static void Utf8(std::string& out, unsigned code) {
		if (code < 0x80) {
			out += static_cast<char>(code);
		} else if (code < 0x800) {
			out += static_cast<char>(0xC0 | (code >> 6));
			out += static_cast<char>(0x80 | (code & 0x3F));
		} else if (code < 0x10000) {
			out += static_cast<char>(0xE0 | (code >> 12));
			out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
			out += static_cast<char>(0x80 | (code & 0x3F));
		} else {
			out += static_cast<char>(0xF0 | (code >> 18));
			out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
			out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
			out += static_cast<char>(0x80 | (code & 0x3F));
		}
	}

	// RFC 8259 strings; raw bytes of 0x80 and above are taken as they come (ids are ASCII; a
	// token that is not matches no token).
	std::optional<std::string> String() {
		if (Peek() != '"') return std::nullopt;
		++at_;
		std::string out;
		while (at_ < text_.size()) {
			const char c = text_[at_++];
			if (c == '"') return out;
			if (static_cast<unsigned char>(c) < 0x20) return std::nullopt;
			if (c != '\\') {
				out += c;
				continue;
			}
			if (at_ >= text_.size()) return std::nullopt;
			switch (text_[at_++]) {
				case '"': out += '"'; break;
				case '\\': out += '\\'; break;
				case '/': out += '/'; break;
				case 'b': out += '\b'; break;
				case 'f': out += '\f'; break;
				case 'n': out += '\n'; break;
				case 'r': out += '\r'; break;
				case 't': out += '\t'; break;
				case 'u': {
					unsigned code = 0;
					if (!Unit(code)) return std::nullopt;
					if (code >= 0xDC00 && code <= 0xDFFF) return std::nullopt;  // a low surrogate alone
					if (code >= 0xD800 && code <= 0xDBFF) {
						unsigned low = 0;
						if (at_ + 2 > text_.size() || text_[at_] != '\\' || text_[at_ + 1] != 'u') return std::nullopt;
						at_ += 2;
						if (!Unit(low) || low < 0xDC00 || low > 0xDFFF) return std::nullopt;
						code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
					}
					Utf8(out, code);
					break;
				}
				default: return std::nullopt;
			}
		}
		return std::nullopt;  // unterminated
	}

	std::string_view text_;
	std::size_t at_ = 0;
};

}  // namespace

std::optional<ClientMessage> ParseClientMessage(std::string_view line) { return Reader(line).Message(); }

std::string Base64Url(const unsigned char* data, std::size_t size) {
	static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
	std::string out;
	std::size_t i = 0;
	for (; i + 3 <= size; i += 3) {
		const unsigned v = (unsigned{data[i]} << 16) | (unsigned{data[i + 1]} << 8) | data[i + 2];
		out += kAlphabet[(v >> 18) & 63];
		out += kAlphabet[(v >> 12) & 63];
		out += kAlphabet[(v >> 6) & 63];
		out += kAlphabet[v & 63];
	}
	if (size - i == 1) {
		const unsigned v = unsigned{data[i]} << 16;
		out += kAlphabet[(v >> 18) & 63];
		out += kAlphabet[(v >> 12) & 63];
	} else if (size - i == 2) {
		const unsigned v = (unsigned{data[i]} << 16) | (unsigned{data[i + 1]} << 8);
		out += kAlphabet[(v >> 18) & 63];
		out += kAlphabet[(v >> 12) & 63];
		out += kAlphabet[(v >> 6) & 63];
	}
	return out;  // no padding: the token goes into URLs
}

}  // namespace monitor_detail

// ---------------------------------------------------------------------------------------------

namespace {

using Clock = std::chrono::steady_clock;
constexpr std::size_t kBlackboardRequestsPerSecond = 10;

std::string NewToken() {
	unsigned char bytes[32];
	std::size_t got = 0;
	while (got < sizeof bytes) {
		const ssize_t n = ::getrandom(bytes + got, sizeof bytes - got, 0);
		if (n < 0) {
			if (errno == EINTR) continue;
			throw std::runtime_error(std::string("monitor: cannot draw a token: ") + std::strerror(errno));
		}
		got += static_cast<std::size_t>(n);
	}
	return monitor_detail::Base64Url(bytes, sizeof bytes);
}

// Compares all of it whatever differs first: how long a refusal takes says nothing of the token.
bool SameToken(std::string_view given, std::string_view token) {
	unsigned char difference = given.size() == token.size() ? 0 : 1;
	for (std::size_t i = 0; i < token.size(); ++i) {
		difference |= static_cast<unsigned char>(token[i] ^ (i < given.size() ? given[i] : 0));
	}
	return difference == 0;
}

// An HTTP request line: a browser or a proxy pointed at the port. Said as such in the notice.
bool LooksLikeHttp(std::string_view line) {
	for (const char* method : {"GET ", "POST ", "PUT ", "HEAD ", "OPTIONS ", "DELETE ", "CONNECT ", "TRACE ", "PATCH "}) {
		if (line.substr(0, std::strlen(method)) == method) return true;
	}
	return false;
}

}  // namespace

struct MonitorServer::Client {
	std::size_t id = 0;
	int fd = -1;
	Clock::time_point since;
	bool greeted = false;
	bool closing = false;            // to be closed at the next Reap()
	std::string in;                  // bytes of a line not complete yet
	std::string out;                 // waiting to be sent, from out_at
	std::size_t out_at = 0;
	std::vector<bool> robots;        // subscribed, by robot
	bool subscribed = false;         // has sent a subscribe
	std::deque<Clock::time_point> asked;  // its last blackboard requests, for the rate limit
};

MonitorServer::MonitorServer(std::vector<std::string> robots, Options options)
	: robots_(std::move(robots)), options_(std::move(options)), watchers_(robots_.size(), 0) {
	token_ = NewToken();
	listener_ = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
	if (listener_ < 0) throw std::runtime_error(std::string("monitor: cannot open a socket: ") + std::strerror(errno));
	sockaddr_in address{};
	address.sin_family = AF_INET;
	address.sin_port = htons(options_.port);
	address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);  // never another interface: the token is the only other guard
	const int yes = 1;
	::setsockopt(listener_, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
	if (::bind(listener_, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0 || ::listen(listener_, 16) != 0) {
		const std::string error = std::strerror(errno);
		::close(listener_);
		throw std::runtime_error("monitor: cannot listen on 127.0.0.1:" + std::to_string(options_.port) + ": " + error);
	}
	sockaddr_in bound{};
	socklen_t length = sizeof bound;
	::getsockname(listener_, reinterpret_cast<sockaddr*>(&bound), &length);
	port_ = ntohs(bound.sin_port);
}

MonitorServer::~MonitorServer() {
	for (auto& client : clients_) {
		if (client->fd >= 0) ::close(client->fd);
	}
	if (listener_ >= 0) ::close(listener_);
}

std::string MonitorServer::Address() const { return "monitor on 127.0.0.1:" + std::to_string(port_) + " token " + token_; }

void MonitorServer::SetWelcome(std::string line) {
	std::lock_guard lock(mutex_);
	welcome_ = std::move(line);
}

void MonitorServer::OnSubscribed(std::function<void(std::size_t, std::size_t)> handler) {
	std::lock_guard lock(mutex_);
	on_subscribed_ = std::move(handler);
}

void MonitorServer::Notice(const std::string& line) const {
	if (options_.notice) {
		options_.notice(line);
	} else {
		std::cerr << "monitor: " << line << "\n";
	}
}

void MonitorServer::Pump() {
	std::lock_guard lock(mutex_);
	if (finished_) return;
	Accept();
	const auto now = Clock::now();
	for (std::size_t i = 0; i < clients_.size(); ++i) {  // by index: a subscribe handler may queue lines
		Client& client = *clients_[i];
		if (client.closing) continue;
		Read(client);
		if (!client.closing && !client.greeted && now - client.since > options_.hello_timeout) {
			Drop(client, "no hello within " + std::to_string(options_.hello_timeout.count()) + " ms", &Stats::refused);
		}
		if (!client.closing) Write(client);
	}
	Reap();
}

void MonitorServer::Accept() {
	for (;;) {
		const int fd = ::accept4(listener_, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
		if (fd < 0) return;  // EAGAIN: nobody else waiting (other errors: try again next time)
		++stats_.accepted;
		if (clients_.size() >= options_.max_clients) {
			::close(fd);
			++stats_.refused;
			Notice("refused a client: already " + std::to_string(clients_.size()) + " clients");
			continue;
		}
		// records are small and a watcher wants them now, not when a segment fills
		const int yes = 1;
		::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &yes, sizeof yes);
		if (options_.kernel_send_buffer > 0) {
			::setsockopt(fd, SOL_SOCKET, SO_SNDBUF, &options_.kernel_send_buffer, sizeof options_.kernel_send_buffer);
		}
		auto client = std::make_unique<Client>();
		client->id = next_id_++;
		client->fd = fd;
		client->since = Clock::now();
		client->robots.assign(robots_.size(), false);
		clients_.push_back(std::move(client));
	}
}

void MonitorServer::Read(Client& client) {
	char buffer[8192];
	for (;;) {
		const ssize_t n = ::recv(client.fd, buffer, sizeof buffer, 0);
		if (n == 0) {
			client.closing = true;  // the client left
			return;
		}
		if (n < 0) {
			if (errno == EINTR) continue;
			if (errno != EAGAIN && errno != EWOULDBLOCK) client.closing = true;
			return;
		}
		std::string_view data(buffer, static_cast<std::size_t>(n));
		while (!data.empty()) {
			const auto end = data.find('\n');
			if (end == std::string_view::npos) {
				if (client.in.size() + data.size() > options_.max_line) {
					Drop(client, "a line longer than " + std::to_string(options_.max_line) + " bytes", &Stats::refused);
					return;
				}
				client.in.append(data);
				break;
			}
			if (client.in.size() + end > options_.max_line) {
				Drop(client, "a line longer than " + std::to_string(options_.max_line) + " bytes", &Stats::refused);
				return;
			}
			client.in.append(data.substr(0, end));
			data.remove_prefix(end + 1);
			const std::string line = std::move(client.in);
			client.in.clear();
			if (Handle(client, line) == Verdict::Close) return;
		}
	}
}

MonitorServer::Verdict MonitorServer::Handle(Client& client, std::string_view line) {
	if (LooksLikeHttp(line)) {
		Drop(client, "an HTTP request (the monitor speaks JSON lines; a browser goes through kse serve)", &Stats::refused);
		return Verdict::Close;
	}
	auto message = monitor_detail::ParseClientMessage(line);
	if (!message) {
		Drop(client, "a line that is not a hello or subscribe message", &Stats::refused);
		return Verdict::Close;
	}
	if (!client.greeted) {
		if (message->type != monitor_detail::ClientMessage::Type::Hello) {
			Drop(client, "a message before its hello", &Stats::refused);
			return Verdict::Close;
		}
		if (!SameToken(message->token, token_)) {
			Drop(client, "a wrong token", &Stats::refused);
			return Verdict::Close;
		}
		client.greeted = true;
		++stats_.greeted;
		if (!welcome_.empty()) Queue(client, welcome_);
		return Verdict::Keep;
	}
	if (message->type == monitor_detail::ClientMessage::Type::Hello) {
		Drop(client, "a second hello", &Stats::refused);
		return Verdict::Close;
	}
	if (message->type == monitor_detail::ClientMessage::Type::Blackboard) {
		// answering costs the program's loop its time: a page asks when its user clicks
		const auto now = Clock::now();
		while (!client.asked.empty() && now - client.asked.front() > std::chrono::seconds(1)) client.asked.pop_front();
		if (client.asked.size() >= kBlackboardRequestsPerSecond) {
			Drop(client, "more than 10 blackboard requests in a second", &Stats::refused);
			return Verdict::Close;
		}
		client.asked.push_back(now);
		const auto& wanted = message->robots.front();
		const auto found = std::find(robots_.begin(), robots_.end(), wanted);
		if (found == robots_.end() || !on_blackboard_) {
			Queue(client, BlackboardRefusal(wanted, found == robots_.end() ? "no such robot" : "this program shows no blackboards"));
		} else {
			on_blackboard_(client.id, static_cast<std::size_t>(found - robots_.begin()));
		}
		return Verdict::Keep;
	}
	// the new set replaces the old; robots it does not know are left out (a page may name one
	// of another match), "*" is every robot
	std::vector<bool> wanted(robots_.size(), false);
	for (const auto& name : message->robots) {
		for (std::size_t r = 0; r < robots_.size(); ++r) {
			if (name == "*" || name == robots_[r]) wanted[r] = true;
		}
	}
	any_subscribed_ = true;
	client.subscribed = true;
	for (std::size_t r = 0; r < robots_.size(); ++r) {
		if (wanted[r] == client.robots[r]) continue;
		client.robots[r] = wanted[r];
		if (wanted[r]) {
			++watchers_[r];
			if (on_subscribed_) on_subscribed_(client.id, r);
		} else {
			--watchers_[r];
		}
	}
	return client.closing ? Verdict::Close : Verdict::Keep;
}

void MonitorServer::Queue(Client& client, std::string_view line) {
	if (client.closing || client.fd < 0) return;
	if (client.out.size() - client.out_at + line.size() + 1 > options_.max_outbound) {
		Drop(client, "did not read: " + std::to_string(options_.max_outbound) + " bytes waited for it", &Stats::overflowed);
		return;
	}
	// what was sent is cut off only now and then, not on every send
	if (client.out_at > 0 && client.out_at >= client.out.size() / 2) {
		client.out.erase(0, client.out_at);
		client.out_at = 0;
	}
	client.out.append(line);
	client.out += '\n';
}

void MonitorServer::Write(Client& client) {
	while (client.out_at < client.out.size()) {
		const ssize_t n = ::send(client.fd, client.out.data() + client.out_at, client.out.size() - client.out_at, MSG_NOSIGNAL);
		if (n < 0) {
			if (errno == EINTR) continue;
			if (errno != EAGAIN && errno != EWOULDBLOCK) client.closing = true;  // EPIPE, ECONNRESET: it left
			return;
		}
		client.out_at += static_cast<std::size_t>(n);
	}
	client.out.clear();
	client.out_at = 0;
}

void MonitorServer::Drop(Client& client, const std::string& why, std::size_t Stats::*count) {
	if (client.closing) return;
	client.closing = true;
	++(stats_.*count);
	Notice("closed client " + std::to_string(client.id) + ": " + why);
}

void MonitorServer::Reap() {
	for (auto& client : clients_) {
		if (!client->closing) continue;
		for (std::size_t r = 0; r < robots_.size(); ++r) {
			if (client->robots[r]) --watchers_[r];
		}
		::close(client->fd);
		client->fd = -1;
	}
	clients_.erase(std::remove_if(clients_.begin(), clients_.end(), [](const auto& c) { return c->fd < 0; }), clients_.end());
}

bool MonitorServer::Wants(std::size_t robot) const noexcept {
	std::lock_guard lock(mutex_);
	return robot < watchers_.size() && watchers_[robot] > 0;
}

void MonitorServer::OnBlackboard(std::function<void(std::size_t client, std::size_t robot)> handler) {
	std::lock_guard lock(mutex_);
	on_blackboard_ = std::move(handler);
}

bool MonitorServer::AnySubscribed() const noexcept {
	std::lock_guard lock(mutex_);
	return any_subscribed_;
}

std::size_t MonitorServer::Subscribers() const {
	std::lock_guard lock(mutex_);
	return static_cast<std::size_t>(std::count_if(clients_.begin(), clients_.end(),
	                                              [](const auto& c) { return c->fd >= 0 && !c->closing && c->subscribed; }));
}

void MonitorServer::Send(std::size_t robot, std::string_view line) {
	std::lock_guard lock(mutex_);
	if (robot >= watchers_.size() || watchers_[robot] == 0) return;
	for (auto& client : clients_) {
		if (client->greeted && client->robots[robot]) Queue(*client, line);
	}
}

void MonitorServer::SendAll(std::string_view line) {
	std::lock_guard lock(mutex_);
	for (auto& client : clients_) {
		if (client->greeted) Queue(*client, line);
	}
}

void MonitorServer::SendTo(std::size_t id, std::string_view line) {
	std::lock_guard lock(mutex_);
	for (auto& client : clients_) {
		if (client->id == id && client->greeted) Queue(*client, line);
	}
}

void MonitorServer::Finish(std::chrono::milliseconds limit) {
	std::lock_guard lock(mutex_);
	if (finished_) return;
	finished_ = true;
	const auto deadline = Clock::now() + limit;
	// Write out, then shut the sending side and read until the client closes: a close() with
	// unread input sends a reset, which may throw away lines the client has not read yet.
	std::vector<bool> shut(clients_.size(), false);
	for (;;) {
		bool waiting = false;
		for (std::size_t i = 0; i < clients_.size(); ++i) {
			Client& client = *clients_[i];
			if (client.closing) continue;
			if (!client.greeted) {
				client.closing = true;  // nothing for it: it never said hello
				continue;
			}
			Write(client);
			if (client.closing) continue;
			if (client.out_at < client.out.size()) {
				waiting = true;
				continue;
			}
			if (!shut[i]) {
				::shutdown(client.fd, SHUT_WR);
				shut[i] = true;
			}
			char buffer[4096];
			const ssize_t n = ::recv(client.fd, buffer, sizeof buffer, 0);
			if (n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
				client.closing = true;
			} else {
				waiting = true;
			}
		}
		if (!waiting || Clock::now() >= deadline) break;
		std::this_thread::sleep_for(std::chrono::milliseconds(2));
	}
	for (auto& client : clients_) client->closing = true;
	Reap();
	::close(listener_);
	listener_ = -1;
}

MonitorServer::Stats MonitorServer::GetStats() const {
	std::lock_guard lock(mutex_);
	return stats_;
}

std::size_t MonitorServer::Clients() const {
	std::lock_guard lock(mutex_);
	return clients_.size();
}

// ---------------------------------------------------------------------------------------------

ChartIndex::ChartIndex(const statechart_engine::Definition& definition) {
	for (const auto* state : definition.States()) states_.push_back(state);
	const auto transitions = definition.Transitions();
	transitions_.reserve(transitions.size());
	for (std::size_t i = 0; i < transitions.size(); ++i) transitions_.emplace(transitions[i], static_cast<long>(i));
}

long ChartIndex::Of(const statechart_engine::TransitionSegmentBase& transition) const {
	const auto found = transitions_.find(&transition);
	return found == transitions_.end() ? -1 : found->second;
}

void ChartIndex::AppendActive(std::string& out, const statechart_engine::Statechart& chart) const {
	out += '[';
	bool first = true;
	for (const auto* state : states_) {
		if (!chart.IsActive(state)) continue;
		if (!first) out += ',';
		AppendJsonString(out, state->Label());
		first = false;
	}
	out += ']';
}

void AppendJsonString(std::string& out, std::string_view text) {
	out += '"';
	for (const char c : text) {
		switch (c) {
			case '"': out += "\\\""; break;
			case '\\': out += "\\\\"; break;
			case '\n': out += "\\n"; break;
			case '\t': out += "\\t"; break;
			default:
				if (static_cast<unsigned char>(c) < 0x20) {
					char escaped[8];
					std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
					out += escaped;
				} else {
					out += c;
				}
		}
	}
	out += '"';
}

double WallMilliseconds() {
	return std::chrono::duration<double, std::milli>(std::chrono::system_clock::now().time_since_epoch()).count();
}

namespace {
void AppendNumber(std::string& out, const char* format, double value) {
	if (value < 0 && value > -0.01) value = 0;  // "-0.00" would differ from the log's "0.00" for the same time
	char text[48];
	const int n = std::snprintf(text, sizeof text, format, value);
	out.append(text, static_cast<std::size_t>(n));
}
}  // namespace

std::string TakenRecord(double t, double wall, std::string_view robot, long tr, const statechart_engine::TransitionSegmentBase& transition) {
	std::string out = "{\"type\":\"taken\",\"t\":";
	AppendNumber(out, "%.2f", t);
	out += ",\"wall\":";
	AppendNumber(out, "%.1f", wall);
	out += ",\"robot\":";
	AppendJsonString(out, robot);
	out += ",\"tr\":";
	out += std::to_string(tr);
	out += ",\"from\":";
	AppendJsonString(out, transition.Source()->Label());
	out += ",\"to\":";
	AppendJsonString(out, transition.Target()->Label());
	if (!transition.Text().empty()) {
		out += ",\"expression\":";
		AppendJsonString(out, transition.Text());
	}
	out += '}';
	return out;
}

std::string ActiveRecord(double t, std::string_view robot, const ChartIndex& index, const statechart_engine::Statechart& chart) {
	std::string out = "{\"type\":\"active\",\"t\":";
	AppendNumber(out, "%.2f", t);
	out += ",\"robot\":";
	AppendJsonString(out, robot);
	out += ",\"active\":";
	index.AppendActive(out, chart);
	out += '}';
	return out;
}

std::string BlackboardRefusal(std::string_view robot, std::string_view why) {
	std::string out = "{\"type\":\"blackboard\",\"robot\":";
	AppendJsonString(out, robot);
	out += ",\"error\":";
	AppendJsonString(out, why);
	out += '}';
	return out;
}

std::string BlackboardRecord(double t, std::string_view robot, const messaging::MessageHub& hub) {
	constexpr std::size_t kLongestText = 2048;
	std::string out = "{\"type\":\"blackboard\",\"t\":";
	AppendNumber(out, "%.2f", t);
	out += ",\"robot\":";
	AppendJsonString(out, robot);
	out += ",\"states\":[";
	const auto now = hub.GetClock().Now();
	google::protobuf::TextFormat::Printer printer;
	printer.SetSingleLineMode(true);
	bool first = true;
	for (const auto& kept : hub.KeptStates()) {
		std::string text;
		printer.PrintToString(*kept.message, &text);
		while (!text.empty() && text.back() == ' ') text.pop_back();
		const bool cut = text.size() > kLongestText;
		if (cut) text.resize(kLongestText);
		out += first ? "{\"topic\":" : ",{\"topic\":";
		first = false;
		AppendJsonString(out, kept.topic);
		out += ",\"type\":";
		AppendJsonString(out, kept.type_name);
		out += ",\"age\":";
		AppendNumber(out, "%.3f", std::chrono::duration<double>(now - kept.time).count());
		out += ",\"text\":";
		AppendJsonString(out, text);
		out += cut ? ",\"cut\":true}" : "}";
	}
	return out + "]}";
}

}  // namespace kse::robot
