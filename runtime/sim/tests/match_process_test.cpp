// kse-match as a process, with behaviours that go wrong (test_behaviours.h): a crash, a hang
// and Ctrl+C each end the run with a message naming what happened and a log whose every line
// is JSON and which holds the match up to that moment; repeated errors are rate-limited and
// name the robot.
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#ifndef KSE_TEST_MATCH
#error "KSE_TEST_MATCH: the path of the test kse-match"
#endif

namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using Clock = std::chrono::steady_clock;

/** Whether a text is one JSON value (RFC 8259), nothing more. */
class JsonChecker {
public:
	static bool Valid(const std::string& text) {
		JsonChecker checker(text);
		return checker.Value() && (checker.Space(), checker.at_ == text.size());
	}

private:
	explicit JsonChecker(const std::string& text) : text_(text) {}
	void Space() {
		while (at_ < text_.size() && (text_[at_] == ' ' || text_[at_] == '\t' || text_[at_] == '\n' || text_[at_] == '\r')) ++at_;
	}
	bool Take(char c) {
		Space();
		if (at_ < text_.size() && text_[at_] == c) {
			++at_;
			return true;
		}
		return false;
	}
	bool Word(const char* word) {
		const std::string w(word);
		if (text_.compare(at_, w.size(), w) != 0) return false;
		at_ += w.size();
		return true;
	}
	bool Digits() {
		const std::size_t from = at_;
		while (at_ < text_.size() && text_[at_] >= '0' && text_[at_] <= '9') ++at_;
		return at_ > from;
	}
	bool Number() {
		if (at_ < text_.size() && text_[at_] == '-') ++at_;
		if (at_ < text_.size() && text_[at_] == '0') {
			++at_;
		} else if (!Digits()) {
			return false;
		}
		if (at_ < text_.size() && text_[at_] == '.' && (++at_, !Digits())) return false;
		if (at_ < text_.size() && (text_[at_] == 'e' || text_[at_] == 'E')) {
			++at_;
			if (at_ < text_.size() && (text_[at_] == '+' || text_[at_] == '-')) ++at_;
			if (!Digits()) return false;
		}
		return true;
	}
	bool String() {
		if (!Take('"')) return false;
		while (at_ < text_.size()) {
			const unsigned char c = static_cast<unsigned char>(text_[at_++]);
			if (c == '"') return true;
			if (c < 0x20) return false;
			if (c != '\\') continue;
			if (at_ >= text_.size()) return false;
			const char escape = text_[at_++];
			if (escape == 'u') {
				for (int i = 0; i < 4; ++i, ++at_) {
					if (at_ >= text_.size() || !std::isxdigit(static_cast<unsigned char>(text_[at_]))) return false;
				}
			} else if (std::string("\"\\/bfnrt").find(escape) == std::string::npos) {
				return false;
			}
		}
		return false;
	}
	bool Value() {
		Space();
		if (at_ >= text_.size()) return false;
		switch (text_[at_]) {
			case '{':
				++at_;
				if (Take('}')) return true;
				do {
					if (!String() || !Take(':') || !Value()) return false;
				} while (Take(','));
				return Take('}');
			case '[':
				++at_;
				if (Take(']')) return true;
				do {
					if (!Value()) return false;
				} while (Take(','));
				return Take(']');
			case '"': return String();
			case 't': return Word("true");
			case 'f': return Word("false");
			case 'n': return Word("null");
			default: return Number();
		}
	}
	const std::string& text_;
	std::size_t at_ = 0;
};

std::string Read(const std::string& path) {
	std::ifstream in(path, std::ios::binary);
	std::ostringstream text;
	text << in.rdbuf();
	return text.str();
}

std::vector<std::string> Lines(const std::string& text) {
	std::vector<std::string> lines;
	std::istringstream in(text);
	for (std::string line; std::getline(in, line);) lines.push_back(line);
	return lines;
}

double Time(const std::string& line) {
	const auto at = line.find("\"t\":");
	return at == std::string::npos ? -1 : std::atof(line.c_str() + at + 4);
}

double LastFrameTime(const std::vector<std::string>& lines) {
	double last = -1;
	for (const auto& line : lines) {
		if (line.rfind("{\"type\":\"frame\"", 0) == 0) last = Time(line);
	}
	return last;
}

/** The test kse-match as a child process, its standard error in a file. */
class Child {
public:
	explicit Child(const std::vector<std::string>& arguments, const std::string& name)
		: err_path_(Scratch(name + ".err")), out_path_(Scratch(name + ".out")) {
		// Everything the child needs is made before fork(): after it, only async-signal-safe calls.
		std::vector<std::string> strings = {KSE_TEST_MATCH};
		strings.insert(strings.end(), arguments.begin(), arguments.end());
		std::vector<char*> argv;
		for (auto& text : strings) argv.push_back(text.data());
		argv.push_back(nullptr);
		// A sanitizer would take the crash for itself: kse-match's own handler is under test.
		std::vector<std::string> environment = {"ASAN_OPTIONS=handle_segv=0:handle_abort=0", "TSAN_OPTIONS=handle_segv=0:handle_abort=0"};
		for (char** variable = environ; *variable != nullptr; ++variable) {
			const std::string text = *variable;
			if (text.rfind("ASAN_OPTIONS=", 0) != 0 && text.rfind("TSAN_OPTIONS=", 0) != 0) environment.push_back(text);
		}
		std::vector<char*> envp;
		for (auto& text : environment) envp.push_back(text.data());
		envp.push_back(nullptr);
		// an earlier run's files must not be read as this one's before the child truncates them
		::unlink(err_path_.c_str());
		::unlink(out_path_.c_str());
		pid_ = fork();
		if (pid_ == 0) {
			const int err = ::open(err_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
			const int out = ::open(out_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
			dup2(err, STDERR_FILENO);
			dup2(out, STDOUT_FILENO);
			execve(argv[0], argv.data(), envp.data());
			_exit(127);
		}
	}
	~Child() {
		if (pid_ > 0 && !waited_) {
			kill(pid_, SIGKILL);
			waitpid(pid_, nullptr, 0);
		}
	}
	/** The wait status, or -1 when the process did not end within the limit (it is killed). */
	int Wait(std::chrono::seconds limit = std::chrono::seconds(60)) {
		const auto end = Clock::now() + limit;
		int status = 0;
		while (Clock::now() < end) {
			if (waitpid(pid_, &status, WNOHANG) == pid_) {
				waited_ = true;
				took_ = Clock::now() - started_;
				return status;
			}
			std::this_thread::sleep_for(std::chrono::milliseconds(5));
		}
		return -1;
	}
	void Signal(int signal) { kill(pid_, signal); }
	int Pid() const { return pid_; }
	std::string Err() const { return Read(err_path_); }
	std::string Out() const { return Read(out_path_); }
	double Seconds() const { return std::chrono::duration<double>(took_).count(); }

	static std::string Scratch(const std::string& name) { return ::testing::TempDir() + "kse_match_process_" + name; }

private:
	std::string err_path_;
	std::string out_path_;
	pid_t pid_ = -1;
	bool waited_ = false;
	Clock::time_point started_ = Clock::now();
	Clock::duration took_{};
};

/** What a monitor client of a kse-match child saw: it connects as the child's line on standard error says, subscribes and reads to the end. */
std::vector<std::string> WatchToTheEnd(const Child& run, const std::string& robots) {
	std::smatch found;
	std::string err;
	const std::regex line("kse-match: monitor on 127\\.0\\.0\\.1:([0-9]+) token ([A-Za-z0-9_-]{43})\n");
	for (const auto end = Clock::now() + std::chrono::seconds(30); Clock::now() < end; std::this_thread::sleep_for(std::chrono::milliseconds(10))) {
		err = run.Err();
		if (std::regex_search(err, found, line)) break;
	}
	if (found.empty()) {
		ADD_FAILURE() << "no monitor line on standard error:\n" << err;
		return {};
	}
	const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
	sockaddr_in address{};
	address.sin_family = AF_INET;
	address.sin_port = htons(static_cast<std::uint16_t>(std::stoi(found[1].str())));
	address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
	EXPECT_EQ(::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0);
	const std::string hello = "{\"type\":\"hello\",\"token\":\"" + found[2].str() + "\"}\n{\"type\":\"subscribe\",\"robots\":[" + robots + "]}\n";
	EXPECT_EQ(::send(fd, hello.data(), hello.size(), MSG_NOSIGNAL), static_cast<ssize_t>(hello.size()));
	std::string text;
	char buffer[65536];
	for (ssize_t n; (n = ::recv(fd, buffer, sizeof buffer, 0)) > 0;) text.append(buffer, static_cast<std::size_t>(n));
	::close(fd);
	return Lines(text);
}

void ExpectEveryLineIsJson(const std::vector<std::string>& lines) {
	ASSERT_FALSE(lines.empty());
	for (std::size_t i = 0; i < lines.size(); ++i) ASSERT_TRUE(JsonChecker::Valid(lines[i])) << "line " << i + 1 << ": " << lines[i];
	EXPECT_EQ(lines.front().rfind("{\"type\":\"match\"", 0), 0u) << lines.front();
}

TEST(JsonChecker, KnowsJsonFromAlmostJson) {
	EXPECT_TRUE(JsonChecker::Valid(R"({"a":[1,-2.5e3,true,null,"x\"\u00e9"],"b":{}})"));
	EXPECT_FALSE(JsonChecker::Valid(R"({"a":[1,2})"));
	EXPECT_FALSE(JsonChecker::Valid(R"({"a":1,"b":[0.12)"));
	EXPECT_FALSE(JsonChecker::Valid(R"({"a":01})"));
	EXPECT_FALSE(JsonChecker::Valid(R"({"a":1} x)"));
}

TEST(MatchProcess, ASegfaultingActivityLeavesAValidLogUpToTheCrash) {
	const std::string log = Child::Scratch("crash.jsonl");
	Child run({"--home", "Crasher:2", "--away", "Chaser:2", "--start-playing", "--duration", "60", "--quiet", "--log", log}, "crash");
	const int status = run.Wait();
	ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status << "\n" << run.Err();
	EXPECT_EQ(WTERMSIG(status), SIGSEGV);
	EXPECT_THAT(run.Err(), HasSubstr("kse-match: crashed (SIGSEGV) while home-2 Crasher ran its behaviour, at t = "));
	const auto lines = Lines(Read(log));
	ExpectEveryLineIsJson(lines);
	// the Crasher's 30th run comes after about 3.5 s of play (a run each 100 ms timer, at the
	// robot's next 30 ms cycle); frames are logged every 0.1 s
	EXPECT_GE(LastFrameTime(lines), 3.0);
	EXPECT_LT(LastFrameTime(lines), 4.0);
	EXPECT_EQ(lines.back().rfind("{\"type\":\"aborted\",\"t\":", 0), 0u) << lines.back();
	EXPECT_THAT(lines.back(), HasSubstr("\"reason\":\"crash\",\"robot\":\"home-2\",\"detail\":\"SIGSEGV\""));
}

TEST(MatchProcess, AHangingActivityEndsTheMatchNamingTheRobot) {
	const std::string log = Child::Scratch("hang.jsonl");
	Child run({"--home", "Hanger:1", "--away", "none", "--start-playing", "--duration", "60", "--quiet", "--hang-limit", "1.5", "--log", log},
	        "hang");
	const int status = run.Wait();
	ASSERT_TRUE(WIFEXITED(status)) << "status " << status << "\n" << run.Err();
	EXPECT_EQ(WEXITSTATUS(status), 3) << run.Err();
	EXPECT_GE(run.Seconds(), 1.5);
	EXPECT_LT(run.Seconds(), 1.5 + 2);
	const std::string err = run.Err();
	EXPECT_THAT(err, HasSubstr("[home-1 Hanger] statechart 'Node_Hang': activity 'Hang' of state 0.2 'Node_Hang' has been running for 1."));
	EXPECT_THAT(err, HasSubstr("kse-match: home-1 Hanger has been stuck for 1."));
	EXPECT_THAT(err, HasSubstr(" s in the activity 'Hang' of state 0.2 'Node_Hang' (statechart 'Node_Hang'): the match cannot go on and ends at t = "));
	const auto lines = Lines(Read(log));
	ExpectEveryLineIsJson(lines);
	EXPECT_GE(LastFrameTime(lines), 2.0);  // the 20th run, after about 2.3 s
	EXPECT_EQ(lines.back().rfind("{\"type\":\"aborted\",\"t\":", 0), 0u) << lines.back();
	EXPECT_THAT(lines.back(), HasSubstr("\"reason\":\"hang\",\"robot\":\"home-1\",\"detail\":\"Hanger stuck for 1."));
}

TEST(MatchProcess, CtrlCLeavesAValidLogThatWasStreamedEverySecond) {
	const std::string log = Child::Scratch("interrupted.jsonl");
	Child run({"--home", "Chaser:1", "--away", "Chaser:1", "--realtime", "--half", "60", "--quiet", "--log", log}, "interrupted");
	std::this_thread::sleep_for(std::chrono::milliseconds(2500));
	// streamed: more than a second of the match is in the file while it runs
	const auto before = Lines(Read(log));
	run.Signal(SIGINT);
	const int status = run.Wait();
	ASSERT_TRUE(WIFEXITED(status)) << "status " << status << "\n" << run.Err();
	EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT);
	ExpectEveryLineIsJson(before);
	EXPECT_GE(LastFrameTime(before), 1.0);
	EXPECT_THAT(run.Err(), HasSubstr("kse-match: interrupted (SIGINT) at t = "));
	const auto lines = Lines(Read(log));
	ExpectEveryLineIsJson(lines);
	EXPECT_GE(LastFrameTime(lines), LastFrameTime(before)) << "and the rest up to the signal";
	EXPECT_THAT(lines.back(), HasSubstr("\"reason\":\"signal\",\"detail\":\"SIGINT\""));
}

TEST(MatchProcess, RepeatedErrorsAreRateLimitedAndNameTheRobot) {
	// 20 s of play, a throw at every run: about 170 failures, printed as three lines and a count
	Child run({"--home", "Thrower:1", "--away", "none", "--start-playing", "--duration", "20", "--quiet"}, "thrower");
	const int status = run.Wait();
	ASSERT_TRUE(WIFEXITED(status)) << "status " << status << "\n" << run.Err();
	EXPECT_EQ(WEXITSTATUS(status), 1) << "behaviour failures";
	const std::string message =
	    "[home-1 Thrower] statechart 'Node_Throw': activity 'Throw' of state 0.2 'Node_Throw' threw: the ball is not where it should be";
	std::size_t full = 0, counted = 0;
	for (const auto& line : Lines(run.Err())) {
		if (line == message) {
			++full;
		} else if (line.rfind(message + " (", 0) == 0) {
			counted += std::stoul(line.substr(message.size() + 2));
		} else {
			ADD_FAILURE() << "unexpected: " << line;
		}
	}
	EXPECT_EQ(full, 3u);
	EXPECT_GE(full + counted, 150u);  // a run each 120 ms: the timer, then the next 30 ms cycle
	EXPECT_LE(full + counted, 200u);
}

}  // namespace

TEST(MatchProcess, ARobotGoingRoundALoopWithoutWaitingIsNamedAndTheMatchEnds) {
	// The Spinner's statechart loops without an activity or a timer: its robot fails at once,
	// the Runner (whose loop waits only for its activity's run) and the match go on.
	const std::string log = Child::Scratch("spinner.jsonl");
	Child run({"--home", "Spinner:1,Runner:2", "--away", "none", "--start-playing", "--duration", "30", "--quiet", "--log", log}, "spinner");
	const int status = run.Wait();
	ASSERT_TRUE(WIFEXITED(status)) << "status " << status << "\n" << run.Err();
	EXPECT_EQ(WEXITSTATUS(status), 1) << "a failed robot\n" << run.Err();
	EXPECT_LT(run.Seconds(), 10) << "no livelock";
	EXPECT_THAT(run.Err(), HasSubstr("[home-1 Spinner] statechart 'Node_spinner': RunUntilStable stopped after 10000 transitions: the statechart "
	                                 "does not settle; it goes round 0.2 'Node_Look' -> 0.3 'Node_0_3' -> 0.2 'Node_Look'"));
	EXPECT_THAT(run.Out(), HasSubstr("  home-1 Spinner failed at 0.0 s and stood still: the statechart took 10000 transitions in one decision "
	                                 "cycle, round 0.2 'Node_Look' -> 0.3 'Node_0_3' -> 0.2 'Node_Look'"));
	EXPECT_THAT(run.Out(), HasSubstr("failed robots: 1"));
	const auto lines = Lines(Read(log));
	ExpectEveryLineIsJson(lines);
	EXPECT_GE(LastFrameTime(lines), 29.9) << "the match went on to its end";
	EXPECT_EQ(lines.back().rfind("{\"type\":\"result\",\"t\":30.00,", 0), 0u) << lines.back();
	EXPECT_THAT(lines.back(), HasSubstr("\"failed\":1"));
	EXPECT_THAT(Read(log), HasSubstr("\"event\":\"failed\",\"team\":0,\"robot\":\"home-1\",\"detail\":\"the statechart took 10000"));
	EXPECT_THAT(Read(log), Not(HasSubstr("\"event\":\"failed\",\"team\":0,\"robot\":\"home-2\"")));
}

TEST(MatchProcess, AMonitoredMatchIsPacedWatchedToTheEndAndLogsTheSame) {
	const std::string plain_log = Child::Scratch("unwatched.jsonl"), watched_log = Child::Scratch("watched.jsonl");
	const std::vector<std::string> match = {"--home", "Patroller:1,Chaser:2", "--away", "Chaser:1", "--seed", "11", "--half", "10", "--start-playing", "--quiet"};
	auto with = [&](std::vector<std::string> more) {
		more.insert(more.begin(), match.begin(), match.end());
		return more;
	};
	Child plain(with({"--log", plain_log}), "unwatched");
	ASSERT_EQ(plain.Wait(), 0) << plain.Err();
	Child watched(with({"--log", watched_log, "--monitor", "--monitor-wait", "--speed", "10"}), "watched");
	const auto lines = WatchToTheEnd(watched, "\"home-1\"");
	ASSERT_EQ(watched.Wait(), 0) << watched.Err();

	EXPECT_TRUE(Read(plain_log) == Read(watched_log)) << "the log differs with --monitor";
	ASSERT_GT(lines.size(), 100u);
	EXPECT_EQ(lines.front().rfind("{\"type\":\"match\",\"monitor\":1,", 0), 0u) << lines.front();
	EXPECT_EQ(lines.back(), Lines(Read(watched_log)).back());
	std::size_t taken = 0, in_log = 0;
	for (const auto& line : lines) {
		ASSERT_TRUE(JsonChecker::Valid(line)) << line;
		if (line.rfind("{\"type\":\"taken\"", 0) == 0) ++taken;
	}
	for (const auto& line : Lines(Read(watched_log))) {
		const auto at = line.find("{\"id\":\"home-1\"");
		if (at == std::string::npos || line.rfind("{\"type\":\"frame\"", 0) != 0) continue;
		const auto list = line.find("\"taken\":[", at);
		const auto end = line.find(']', list);
		for (auto quote = line.find('"', list + 9); quote < end; quote = line.find('"', line.find('"', quote + 1) + 1)) ++in_log;
	}
	EXPECT_EQ(taken, in_log);
	// ten match seconds at ten times real speed take about one: never much less (no upper bound,
	// a loaded machine may be slow)
	EXPECT_GE(watched.Seconds(), 0.8) << watched.Err();
}

TEST(MatchProcess, AMonitorClientGetsTheAbortedRecordOfAHang) {
	Child run({"--home", "Hanger:2", "--away", "none", "--start-playing", "--duration", "60", "--quiet", "--hang-limit", "1", "--monitor", "--monitor-wait"}, "watched-hang");
	const auto lines = WatchToTheEnd(run, "\"*\"");
	const int status = run.Wait();
	ASSERT_TRUE(WIFEXITED(status)) << run.Err();
	EXPECT_EQ(WEXITSTATUS(status), 3);
	ASSERT_FALSE(lines.empty());
	EXPECT_THAT(lines.back(), HasSubstr("{\"type\":\"aborted\","));
	EXPECT_THAT(lines.back(), HasSubstr("\"reason\":\"hang\",\"robot\":\"home-2\""));
}

// The discovery folder (MatchDiscovery.h): a watched match announces itself privately for as long
// as it runs, and neither the end nor Ctrl+C, a hang or a crash leaves the announcement behind.
class Announcement : public ::testing::Test {
protected:
	void SetUp() override {
		runtime_ = Child::Scratch("xdg-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
		std::system(("rm -rf '" + runtime_ + "'").c_str());
		::mkdir(runtime_.c_str(), 0700);
		const char* before = std::getenv("XDG_RUNTIME_DIR");
		had_ = before != nullptr;
		if (had_) before_ = before;
		::setenv("XDG_RUNTIME_DIR", runtime_.c_str(), 1);  // the child inherits it
	}
	void TearDown() override {
		if (had_) {
			::setenv("XDG_RUNTIME_DIR", before_.c_str(), 1);
		} else {
			::unsetenv("XDG_RUNTIME_DIR");
		}
	}
	std::string Folder() const { return runtime_ + "/kse/matches"; }
	/** The child's announcement, once it is there (empty after 30 s without). */
	std::string WaitForFile(int pid) const {
		const std::string path = Folder() + "/" + std::to_string(pid) + ".json";
		for (const auto end = Clock::now() + std::chrono::seconds(30); Clock::now() < end; std::this_thread::sleep_for(std::chrono::milliseconds(10))) {
			if (::access(path.c_str(), F_OK) == 0) return path;
		}
		return {};
	}
	static unsigned Mode(const std::string& path) {
		struct stat status {};
		return ::stat(path.c_str(), &status) == 0 ? status.st_mode & 07777 : 0;
	}
	/** Whether the folder holds no file at all (no announcement, no temporary file). */
	bool Empty() const {
		const std::string listing = Child::Scratch("listing");
		std::system(("ls -A '" + Folder() + "' > '" + listing + "'").c_str());
		return Read(listing).empty();
	}

	std::string runtime_;
	std::string before_;
	bool had_ = false;
};

TEST_F(Announcement, AWatchedMatchIsListedPrivatelyWhileItRunsAndNotAfter) {
	Child run({"--home", "Chaser:1", "--away", "Chaser:1", "--seed", "4", "--half", "2", "--start-playing", "--quiet", "--monitor", "--monitor-wait"}, "announced");
	const std::string path = WaitForFile(run.Pid());
	ASSERT_FALSE(path.empty()) << "no announcement in " << Folder() << "\n" << run.Err();
	EXPECT_EQ(Mode(path), 0600u);
	EXPECT_EQ(Mode(Folder()), 0700u);
	EXPECT_EQ(Mode(runtime_ + "/kse"), 0700u);
	const std::string json = Read(path);
	EXPECT_TRUE(JsonChecker::Valid(json)) << json;
	std::smatch address;
	const std::string err = run.Err();
	ASSERT_TRUE(std::regex_search(err, address, std::regex("monitor on 127\\.0\\.0\\.1:([0-9]+) token (\\S+)"))) << err;
	EXPECT_THAT(json, HasSubstr("{\"pid\":" + std::to_string(run.Pid()) + ",\"port\":" + address[1].str() + ",\"token\":\"" + address[2].str() + "\",\"started\":"));
	EXPECT_THAT(json, HasSubstr("\"seed\":4,"));
	EXPECT_THAT(json, HasSubstr("{\"id\":\"home-1\",\"number\":1,\"behaviour\":\"Chaser\"}"));
	EXPECT_THAT(json, HasSubstr("{\"id\":\"away-1\",\"number\":1,\"behaviour\":\"Chaser\"}"));
	WatchToTheEnd(run, "\"home-1\"");
	ASSERT_EQ(run.Wait(), 0) << run.Err();
	EXPECT_NE(::access(path.c_str(), F_OK), 0) << path << " is still there after the match";
	EXPECT_TRUE(Empty());
}

TEST_F(Announcement, AnOlderFolderOpenToOthersIsMadePrivate) {
	::mkdir((runtime_ + "/kse").c_str(), 0755);
	::mkdir(Folder().c_str(), 0777);
	::chmod(Folder().c_str(), 0777);  // the umask may have narrowed it
	Child run({"--home", "Chaser:1", "--away", "none", "--start-playing", "--quiet", "--monitor", "--monitor-wait"}, "narrowed");
	ASSERT_FALSE(WaitForFile(run.Pid()).empty()) << run.Err();
	EXPECT_EQ(Mode(Folder()), 0700u);
	EXPECT_EQ(Mode(runtime_ + "/kse"), 0700u);
}

TEST_F(Announcement, CtrlCRemovesIt) {
	Child run({"--home", "Chaser:1", "--away", "none", "--start-playing", "--quiet", "--monitor", "--monitor-wait"}, "announced-int");
	const std::string path = WaitForFile(run.Pid());
	ASSERT_FALSE(path.empty()) << run.Err();
	run.Signal(SIGINT);
	const int status = run.Wait();
	ASSERT_TRUE(WIFEXITED(status)) << run.Err();
	EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT);
	EXPECT_NE(::access(path.c_str(), F_OK), 0) << path << " is still there after SIGINT";
	EXPECT_TRUE(Empty());
}

TEST_F(Announcement, AHangRemovesIt) {
	Child run({"--home", "Hanger:1", "--away", "none", "--start-playing", "--duration", "60", "--quiet", "--hang-limit", "1", "--monitor"}, "announced-hang");
	ASSERT_FALSE(WaitForFile(run.Pid()).empty()) << run.Err();
	const int status = run.Wait();
	ASSERT_TRUE(WIFEXITED(status)) << run.Err();
	EXPECT_EQ(WEXITSTATUS(status), 3);
	EXPECT_THAT(run.Err(), HasSubstr("monitor on 127.0.0.1:"));
	EXPECT_NE(::access((Folder() + "/" + std::to_string(run.Pid()) + ".json").c_str(), F_OK), 0);
	EXPECT_TRUE(Empty());
}

TEST_F(Announcement, ACrashRemovesIt) {
	// paced: the crash comes about 3.5 match seconds in, and the announcement must be seen before it
	Child run({"--home", "Crasher:2", "--away", "Chaser:2", "--start-playing", "--duration", "60", "--quiet", "--monitor", "--speed", "2"}, "announced-crash");
	ASSERT_FALSE(WaitForFile(run.Pid()).empty()) << run.Err();
	const int status = run.Wait();
	ASSERT_TRUE(WIFSIGNALED(status)) << run.Err();
	EXPECT_THAT(run.Err(), HasSubstr("kse-match: crashed (SIGSEGV)"));
	EXPECT_NE(::access((Folder() + "/" + std::to_string(run.Pid()) + ".json").c_str(), F_OK), 0);
	EXPECT_TRUE(Empty());
}
