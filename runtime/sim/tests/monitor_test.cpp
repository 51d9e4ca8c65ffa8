// The live monitor (docs/monitor.md) as a watcher meets it: real matches with MatchMonitor and
// loopback clients. Clients that break the protocol lose their connection and nothing else;
// what a subscribed client gets is what the match log says the robot did; the log is the same
// with a monitor as without.
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include <kse/robot/MonitorServer.h>
#include <kse/sim/Match.h>
#include <kse/sim/MatchLog.h>
#include <kse/sim/MatchMonitor.h>

#include "test_behaviours.h"

using namespace kse::sim;
using kse::robot::MonitorServer;

namespace {

/** A watcher on the other end of the socket; reads without blocking, so one thread runs match and clients. */
class TestClient {
public:
	explicit TestClient(std::uint16_t port, int receive_buffer = 0) {
		fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
		// before connect(): the window it advertises follows it
		if (receive_buffer > 0) ::setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &receive_buffer, sizeof receive_buffer);
		sockaddr_in address{};
		address.sin_family = AF_INET;
		address.sin_port = htons(port);
		address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
		connected_ = ::connect(fd_, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0;
	}
	~TestClient() { ::close(fd_); }

	bool Connected() const { return connected_; }
	void Send(const std::string& text) { ASSERT_EQ(::send(fd_, text.data(), text.size(), MSG_NOSIGNAL), static_cast<ssize_t>(text.size())); }
	void Hello(const std::string& token) { Send("{\"type\":\"hello\",\"token\":\"" + token + "\"}\n"); }
	void Subscribe(const std::string& robots) { Send("{\"type\":\"subscribe\",\"robots\":[" + robots + "]}\n"); }

	/** Reads what is there; true once the server closed (end of stream or reset). */
	bool Poll() {
		char buffer[65536];
		while (!closed_) {
			const ssize_t n = ::recv(fd_, buffer, sizeof buffer, MSG_DONTWAIT);
			if (n > 0) {
				bytes_ += static_cast<std::size_t>(n);
				in_.append(buffer, static_cast<std::size_t>(n));
				continue;
			}
			if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
			closed_ = true;
		}
		for (auto end = in_.find('\n'); end != std::string::npos; end = in_.find('\n')) {
			lines_.push_back(in_.substr(0, end));
			in_.erase(0, end + 1);
		}
		return closed_;
	}
	/** Polls, and pumps {@code server} when given, until closed or {@code limit}. */
	bool WaitClosed(MonitorServer* server = nullptr, std::chrono::milliseconds limit = std::chrono::seconds(10)) {
		const auto end = std::chrono::steady_clock::now() + limit;
		while (!Poll() && std::chrono::steady_clock::now() < end) {
			if (server) server->Pump();
			std::this_thread::sleep_for(std::chrono::milliseconds(2));
		}
		return closed_;
	}
	const std::vector<std::string>& Lines() const { return lines_; }
	std::size_t Bytes() const { return bytes_; }

private:
	int fd_ = -1;
	bool connected_ = false;
	bool closed_ = false;
	std::size_t bytes_ = 0;
	std::string in_;
	std::vector<std::string> lines_;
};

MatchConfig Patrollers(std::uint64_t seed) {
	MatchConfig config;
	config.seed = seed;
	config.start_playing = true;
	config.referee.half_seconds = 20;
	config.home.players = {{"Patroller", 1, std::nullopt, {}}, {"Chaser", 2, std::nullopt, {}}};
	config.away.players = {{"Patroller", 1, std::nullopt, {}}, {"Chaser", 2, std::nullopt, {}}};
	return config;
}

MonitorServer::Options Quiet() {
	MonitorServer::Options options;
	options.notice = [](const std::string&) {};  // the tests look at the sockets and the counts
	// the clients are read on the match's thread: they cannot close before the match is over
	options.finish_limit = std::chrono::milliseconds(50);
	return options;
}

// The value of a string or number member of a flat record ("" when absent).
std::string Field(const std::string& line, const std::string& name) {
	const std::string key = "\"" + name + "\":";
	const auto at = line.find(key);
	if (at == std::string::npos) return "";
	auto begin = at + key.size();
	if (line[begin] == '"') return line.substr(begin + 1, line.find('"', begin + 1) - begin - 1);
	return line.substr(begin, line.find_first_of(",}", begin) - begin);
}

// The strings of an array member: "active":["a","b"].
std::vector<std::string> Strings(const std::string& line, const std::string& name, std::size_t from = 0) {
	std::vector<std::string> values;
	const std::string key = "\"" + name + "\":[";
	const auto at = line.find(key, from);
	if (at == std::string::npos) return values;
	const auto end = line.find(']', at);
	for (auto quote = line.find('"', at + key.size()); quote < end; quote = line.find('"', quote + 1)) {
		const auto close = line.find('"', quote + 1);
		values.push_back(line.substr(quote + 1, close - quote - 1));
		quote = close;
	}
	return values;
}

std::string Type(const std::string& line) { return Field(line, "type"); }

std::vector<std::string> OfType(const std::vector<std::string>& lines, const std::string& type) {
	std::vector<std::string> found;
	for (const auto& line : lines) {
		if (Type(line) == type) found.push_back(line);
	}
	return found;
}

/** A match with a monitor, the clients polled after every tick; {@code during} runs once a (match) second. */
struct Watched {
	explicit Watched(const MatchConfig& config, MonitorServer::Options options = Quiet()) : match(config), log(text), monitor(match, options) {
		match.AddObserver(log);
		match.AddObserver(monitor);
	}
	void Run(std::vector<TestClient*> clients, const std::function<void(const Match&)>& during = {}) {
		match.Run(0, [&](const Match& m) {
			for (auto* client : clients) client->Poll();
			if (during) during(m);
		});
		for (auto* client : clients) client->WaitClosed();
	}
	std::ostringstream text;
	Match match;
	JsonLinesLog log;
	MatchMonitor monitor;
};

std::vector<std::string> LogLines(const std::string& text) {
	std::vector<std::string> lines;
	std::istringstream in(text);
	for (std::string line; std::getline(in, line);) lines.push_back(line);
	return lines;
}

/** The "robots" entry of {@code robot} in a frame of the log. */
std::string RobotInFrame(const std::string& frame, const std::string& robot) {
	const auto at = frame.find("{\"id\":\"" + robot + "\"");
	return at == std::string::npos ? "" : frame.substr(at, frame.find("]}", frame.find("\"taken\":[", at)) - at + 2);
}

}  // namespace

TEST(MonitorMessages, HelloAndSubscribeAreReadStrictly) {
	using kse::robot::monitor_detail::ParseClientMessage;
	auto hello = ParseClientMessage(R"( { "type" : "hello", "token":"a\/b\u0041" } )");
	ASSERT_TRUE(hello);
	EXPECT_EQ(hello->token, "a/bA");
	auto subscribe = ParseClientMessage(R"({"robots":["home-1","*"],"type":"subscribe"})");
	ASSERT_TRUE(subscribe);
	EXPECT_EQ(subscribe->robots, (std::vector<std::string>{"home-1", "*"}));
	for (const char* bad : {"", "{}", "[]", "\"hello\"", R"({"type":"hello"})", R"({"type":"hello","token":"x","token":"y"})",
	                        R"({"type":"hello","token":"x"} x)", R"({"type":"hello","token":"x",})", R"({"type":"hello","token":1})",
	                        R"({"type":"subscribe","robots":"home-1"})", R"({"type":"subscribe","robots":[1]})", R"({"type":"subscribe"})",
	                        R"({"type":"pause"})", R"({"type":"hello","token":"x","robots":[]})", R"({"type":"hello","token":"\x"})",
	                        R"({"type":"hello","token":"\ud800"})", "{\"type\":\"hello\",\"token\":\"a\tb\"}", R"({"type":"hello","token":"x)"}) {
		EXPECT_FALSE(ParseClientMessage(bad)) << bad;
	}
}

TEST(MonitorMessages, TheTokenIs32RandomBytesInBase64Url) {
	using kse::robot::monitor_detail::Base64Url;
	const unsigned char bytes[] = {0xfb, 0xff, 0x00, 'f', 'o'};
	EXPECT_EQ(Base64Url(bytes, 3), "-_8A");
	EXPECT_EQ(Base64Url(bytes + 3, 2), "Zm8");
	MonitorServer one({"home-1"}, Quiet()), two({"home-1"}, Quiet());
	EXPECT_EQ(one.Token().size(), 43u);
	EXPECT_EQ(one.Token().find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_"), std::string::npos);
	EXPECT_NE(one.Token(), two.Token());
	EXPECT_EQ(one.Address(), "monitor on 127.0.0.1:" + std::to_string(one.Port()) + " token " + one.Token());
}

TEST(Monitor, AWrongTokenAnHttpRequestAndNoHelloInTimeAreClosedWithNothingSent) {
	auto options = Quiet();
	options.hello_timeout = std::chrono::milliseconds(200);
	MonitorServer server({"home-1"}, options);
	server.SetWelcome("{\"type\":\"match\"}");
	TestClient wrong(server.Port()), http(server.Port()), silent(server.Port()), good(server.Port());
	wrong.Hello(std::string(server.Token().size(), 'A'));
	http.Send("GET /monitor HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
	good.Hello(server.Token());
	EXPECT_TRUE(wrong.WaitClosed(&server));
	EXPECT_TRUE(http.WaitClosed(&server));
	EXPECT_TRUE(silent.WaitClosed(&server));
	EXPECT_EQ(wrong.Bytes() + http.Bytes() + silent.Bytes(), 0u);
	// the good one is still there and was welcomed
	good.Poll();
	EXPECT_EQ(good.Lines(), std::vector<std::string>{"{\"type\":\"match\"}"});
	EXPECT_FALSE(good.Poll());
	EXPECT_EQ(server.GetStats().refused, 3u);
	EXPECT_EQ(server.Clients(), 1u);
}

TEST(Monitor, AMessageBeforeHelloASecondHelloAndUnknownTypesClose) {
	MonitorServer server({"home-1"}, Quiet());
	TestClient early(server.Port()), twice(server.Port()), unknown(server.Port());
	early.Subscribe("\"*\"");
	twice.Hello(server.Token());
	twice.Hello(server.Token());
	unknown.Hello(server.Token());
	unknown.Send("{\"type\":\"pause\"}\n");
	EXPECT_TRUE(early.WaitClosed(&server));
	EXPECT_TRUE(twice.WaitClosed(&server));
	EXPECT_TRUE(unknown.WaitClosed(&server));
	EXPECT_EQ(early.Bytes(), 0u);
}

TEST(Monitor, ABlackboardRequestIsAnsweredWithTheStateMessagesTheRobotHolds) {
	Watched watched(Patrollers(1));
	auto& server = watched.monitor.Server();
	TestClient client(server.Port());
	client.Hello(server.Token());
	client.Subscribe("\"home-1\"");
	client.Send("{\"type\":\"blackboard\",\"robot\":\"nobody\"}\n");
	bool asked = false;
	watched.Run({&client}, [&](const Match& match) {
		if (!asked && match.Time() >= 5) {
			client.Send("{\"type\":\"blackboard\",\"robot\":\"home-1\"}\n");
			asked = true;
		}
	});
	const auto answers = OfType(client.Lines(), "blackboard");
	ASSERT_EQ(answers.size(), 2u) << client.Lines().size();
	EXPECT_EQ(answers[0], "{\"type\":\"blackboard\",\"robot\":\"nobody\",\"error\":\"no such robot\"}");
	// mid-match, the game controller's state reached the robot: PLAYING, as the log says
	EXPECT_EQ(answers[1].rfind("{\"type\":\"blackboard\",\"t\":5.", 0), 0u) << answers[1];
	EXPECT_NE(answers[1].find("\"robot\":\"home-1\",\"states\":[{\"topic\":"), std::string::npos) << answers[1];
	EXPECT_NE(answers[1].find("\"type\":\"GameStateMessage\""), std::string::npos) << answers[1];
	EXPECT_NE(answers[1].find("player_state: 3"), std::string::npos) << answers[1];
	EXPECT_EQ(server.GetStats().refused, 0u);
}

TEST(Monitor, MoreThanTenBlackboardRequestsInASecondCloseThatClientOnly) {
	Watched watched(Patrollers(1));
	auto& server = watched.monitor.Server();
	TestClient greedy(server.Port()), calm(server.Port());
	greedy.Hello(server.Token());
	calm.Hello(server.Token());
	calm.Subscribe("\"*\"");
	std::string burst;
	for (int i = 0; i < 11; ++i) burst += "{\"type\":\"blackboard\",\"robot\":\"home-1\"}\n";
	greedy.Send(burst);
	EXPECT_TRUE(greedy.WaitClosed(&server));
	EXPECT_EQ(server.GetStats().refused, 1u);
	EXPECT_EQ(server.Clients(), 1u);
}

TEST(Monitor, AMatchWaitsForAsManyWatchersAsItWasToldAndCountsOnlyThoseConnected) {
	Watched watched(Patrollers(1));
	auto& server = watched.monitor.Server();
	{
		TestClient gone(server.Port());
		gone.Hello(server.Token());
		gone.Subscribe("\"*\"");
		ASSERT_TRUE(watched.monitor.WaitForSubscribers(1, std::chrono::seconds(10)));
	}
	TestClient first(server.Port()), greeted(server.Port());
	first.Hello(server.Token());
	first.Subscribe("\"home-1\"");
	greeted.Hello(server.Token());  // connected and greeted, but watching nothing yet
	EXPECT_FALSE(watched.monitor.WaitForSubscribers(2, std::chrono::milliseconds(300)));
	EXPECT_EQ(server.Subscribers(), 1u);
	greeted.Subscribe("\"away-1\"");
	EXPECT_TRUE(watched.monitor.WaitForSubscribers(2, std::chrono::seconds(10)));
}

TEST(Monitor, ASubscriberGetsExactlyItsRobotsTransitionsAsTheLogListsThem) {
	Watched watched(Patrollers(3));
	TestClient client(watched.monitor.Server().Port());
	client.Hello(watched.monitor.Server().Token());
	client.Subscribe("\"home-1\"");
	// another watcher, of another robot: its records must not reach the first
	TestClient other(watched.monitor.Server().Port());
	other.Hello(watched.monitor.Server().Token());
	other.Subscribe("\"away-1\"");
	ASSERT_TRUE(watched.monitor.WaitForSubscribers(2, std::chrono::seconds(10)));
	watched.Run({&client, &other});
	EXPECT_GT(OfType(other.Lines(), "taken").size(), 100u);
	for (const auto& line : other.Lines()) {
		if (Type(line) == "taken" || Type(line) == "active") EXPECT_EQ(Field(line, "robot"), "away-1") << line;
	}

	const auto& lines = client.Lines();
	ASSERT_GE(lines.size(), 3u);
	EXPECT_EQ(lines.front().rfind("{\"type\":\"match\",\"monitor\":1,\"version\":1,\"seed\":3,", 0), 0u) << lines.front();
	EXPECT_NE(lines.front().find("{\"id\":\"home-1\",\"behaviour\":\"Patroller\",\"states\":5,\"transitions\":4}"), std::string::npos) << lines.front();
	EXPECT_EQ(Type(lines.back()), "result");
	// at once on subscribing: its configuration then (before the start: the root and its START)
	EXPECT_EQ(lines[1], "{\"type\":\"active\",\"t\":0.00,\"robot\":\"home-1\",\"active\":[\"0\",\"0.1\"]}");

	std::vector<std::string> records;
	for (const auto& line : lines) {
		if (Type(line) == "taken" || Type(line) == "active") {
			EXPECT_EQ(Field(line, "robot"), "home-1") << line;
			records.push_back(line);
		}
	}
	const auto taken = OfType(lines, "taken");
	ASSERT_GT(taken.size(), 100u);

	// tr names the transition in the definition's model order; the log names them
	const auto transitions = watched.match.GetRobot(0)->Chart().Transitions();
	std::vector<std::string> from_monitor;
	std::map<std::string, int> by_index;
	for (const auto& line : taken) {
		const auto tr = std::stoul(Field(line, "tr"));
		ASSERT_LT(tr, transitions.size()) << line;
		from_monitor.push_back(transitions[tr]->Name());
		EXPECT_EQ(Field(line, "from"), transitions[tr]->Source()->Label()) << line;
		EXPECT_EQ(Field(line, "to"), transitions[tr]->Target()->Label()) << line;
		// the model's expression, where the chart has one (the two self-loops of 0.2.2)
		EXPECT_EQ(line.find("\"expression\":") != std::string::npos, !transitions[tr]->Text().empty()) << line;
		if (!transitions[tr]->Text().empty()) EXPECT_EQ(Field(line, "expression"), transitions[tr]->Text()) << line;
		++by_index[Field(line, "tr")];
		EXPECT_GT(std::stod(Field(line, "wall")), 1.7e12) << line;  // milliseconds since 1970, now
	}
	// both self-transitions of 0.2.2 (one name, two indexes) were taken and told apart
	EXPECT_GT(by_index["2"], 0);
	EXPECT_GT(by_index["3"], 0);
	EXPECT_GT(by_index["2"], by_index["3"]);  // [tick] every 100 ms, [tock] every 250 ms: a swap of the two shows
	std::vector<std::string> from_log;
	std::string last_frame;
	for (const auto& line : LogLines(watched.text.str())) {
		if (Type(line) != "frame") continue;
		last_frame = line;
		const auto names = Strings(RobotInFrame(line, "home-1"), "taken");
		from_log.insert(from_log.end(), names.begin(), names.end());
	}
	EXPECT_EQ(from_monitor, from_log);

	// the last configuration sent is the last the log shows, as labels
	std::map<std::string, std::string> label_of;
	for (const auto* state : watched.match.GetRobot(0)->Chart().States()) label_of[state->Name()] = state->Label();
	std::vector<std::string> expected;
	for (const auto& name : Strings(RobotInFrame(last_frame, "home-1"), "active")) expected.push_back(label_of.at(name));
	EXPECT_EQ(expected, (std::vector<std::string>{"0", "0.2", "0.2.2"}));
	EXPECT_EQ(Strings(OfType(lines, "active").back(), "active"), expected);

	// every frame, every event and the result, as for every client
	const auto log_lines = LogLines(watched.text.str());
	EXPECT_EQ(OfType(lines, "frame").size(), OfType(log_lines, "frame").size());
	EXPECT_EQ(OfType(lines, "event"), OfType(log_lines, "event"));
	EXPECT_EQ(lines.back(), log_lines.back());
}

TEST(Monitor, ASubscribeReplacesTheRobotsAndStartsWithTheirConfiguration) {
	Watched watched(Patrollers(4));
	TestClient client(watched.monitor.Server().Port());
	client.Hello(watched.monitor.Server().Token());
	client.Subscribe("\"home-1\"");
	std::size_t switched = 0;
	watched.Run({&client}, [&](const Match& m) {
		if (switched == 0 && m.Time() >= 5) {
			client.Subscribe("\"away-1\",\"nobody\"");
			switched = client.Lines().size();
		}
	});
	ASSERT_GT(switched, 0u);
	const auto& lines = client.Lines();
	bool away_started = false;
	std::size_t home_after = 0, away = 0;
	for (std::size_t i = switched; i < lines.size(); ++i) {
		const auto robot = Field(lines[i], "robot");
		if (Type(lines[i]) != "taken" && Type(lines[i]) != "active") continue;
		if (robot == "away-1") {
			// its first record is its whole configuration, mid-match
			if (!away_started) EXPECT_EQ(Strings(lines[i], "active"), (std::vector<std::string>{"0", "0.2", "0.2.2"})) << lines[i];
			away_started = true;
			++away;
		} else if (away_started) {
			++home_after;  // home-1's records may still arrive until the subscribe is read
		}
	}
	EXPECT_GT(away, 50u);
	EXPECT_EQ(home_after, 0u);
}

TEST(Monitor, AnOversizedLineClosesThatClientWhileAnotherReceivesToTheEnd) {
	Watched watched(Patrollers(5));
	TestClient rude(watched.monitor.Server().Port()), good(watched.monitor.Server().Port());
	rude.Hello(watched.monitor.Server().Token());
	good.Hello(watched.monitor.Server().Token());
	rude.Subscribe("\"*\"");
	good.Subscribe("\"*\"");
	bool sent = false;
	std::size_t rude_lines = 0;
	watched.Run({&rude, &good}, [&](const Match& m) {
		if (!sent && m.Time() >= 3) {
			rude.Send("{\"type\":\"subscribe\",\"robots\":[\"" + std::string(5 * 1024, 'x') + "\"]}\n");
			sent = true;
		}
		if (sent && rude.Poll() && rude_lines == 0) rude_lines = rude.Lines().size();
	});
	EXPECT_TRUE(rude.Poll());
	EXPECT_NE(Type(rude.Lines().back()), "result");
	EXPECT_EQ(Type(good.Lines().back()), "result");
	EXPECT_GT(OfType(good.Lines(), "taken").size(), OfType(rude.Lines(), "taken").size() + 100);
	EXPECT_EQ(watched.monitor.Server().GetStats().refused, 1u);
	EXPECT_EQ(watched.match.GetReferee().State(), GameState::Finished);
}

TEST(Monitor, AClientThatNeverReadsIsClosedAndTheMatchFinishes) {
	auto options = Quiet();
	// the 8 MiB of kse-match, and the megabytes the kernel holds on its own, would need a long match to fill
	options.max_outbound = 64 * 1024;
	options.kernel_send_buffer = 16 * 1024;
	Watched watched(Patrollers(6), options);
	TestClient sleeper(watched.monitor.Server().Port(), 4096), reader(watched.monitor.Server().Port());
	sleeper.Hello(watched.monitor.Server().Token());
	sleeper.Subscribe("\"*\"");
	reader.Hello(watched.monitor.Server().Token());
	reader.Subscribe("\"*\"");
	watched.match.Run(0, [&](const Match&) { reader.Poll(); });  // the sleeper is never read during the match
	EXPECT_TRUE(reader.WaitClosed());
	EXPECT_EQ(Type(reader.Lines().back()), "result");
	EXPECT_EQ(watched.monitor.Server().GetStats().overflowed, 1u);
	EXPECT_EQ(watched.match.GetReferee().State(), GameState::Finished);
	// what it gets now is what the kernel held for it, and then the end: no result line
	EXPECT_TRUE(sleeper.WaitClosed());
	EXPECT_LT(sleeper.Bytes(), reader.Bytes());
}

TEST(Monitor, TheLogIsTheSameByteForByteWithAndWithoutAMonitor) {
	const MatchConfig config = Patrollers(7);
	std::ostringstream alone;
	{
		JsonLinesLog log(alone);
		Match match(config);
		match.AddObserver(log);
		match.Run(0);
	}
	Watched watched(config);
	TestClient client(watched.monitor.Server().Port());
	client.Hello(watched.monitor.Server().Token());
	client.Subscribe("\"*\"");
	watched.Run({&client});
	EXPECT_GT(OfType(client.Lines(), "taken").size(), 500u);
	EXPECT_GT(alone.str().size(), 10000u);
	EXPECT_TRUE(alone.str() == watched.text.str()) << "the log differs with a monitor";
}
