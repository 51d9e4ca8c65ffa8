// What a match tells about its robots' engines (every line names the robot, repeats are
// rate-limited) and how its log reaches the disk (streamed in whole lines).
#include <unistd.h>

#include <fstream>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <kse/sim/LogFile.h>
#include <kse/sim/Match.h>
#include <kse/sim/MatchLog.h>
#include <kse/sim/RobotReports.h>

#include "test_behaviours.h"

using namespace kse::sim;
using ::testing::HasSubstr;
using ::testing::StartsWith;
using statechart_engine::EngineReport;

namespace {

class Lines {
public:
	RobotReports::Printer Printer() {
		return [this](const std::string& line) {
			std::lock_guard<std::mutex> lock(mutex_);
			lines_.push_back(line);
		};
	}
	std::vector<std::string> All() const {
		std::lock_guard<std::mutex> lock(mutex_);
		return lines_;
	}

private:
	mutable std::mutex mutex_;
	std::vector<std::string> lines_;
};

EngineReport Failure(const std::string& text) {
	EngineReport report;
	report.kind = EngineReport::Kind::Failure;
	report.chart = "Node_x";
	report.text = text;
	return report;
}

std::string Read(const std::string& path) {
	std::ifstream in(path, std::ios::binary);
	std::ostringstream text;
	text << in.rdbuf();
	return text.str();
}

std::string Scratch(const std::string& name) { return ::testing::TempDir() + "kse_reports_test_" + name; }

}  // namespace

TEST(RobotReports, RepeatsPrintTheFirstFewThenACountEachPeriod) {
	Lines lines;
	RobotReports reports(RobotReports::Limits{3, std::chrono::milliseconds(50)});
	reports.SetPrinter(lines.Printer());
	const auto reporter = reports.For("home-2", "Defender");
	for (int i = 0; i < 10; ++i) reporter(Failure("boom"));
	reporter(Failure("another message"));
	const std::string boom = "[home-2 Defender] statechart 'Node_x': boom";
	EXPECT_EQ(lines.All(), (std::vector<std::string>{boom, boom, boom, "[home-2 Defender] statechart 'Node_x': another message"}));
	std::this_thread::sleep_for(std::chrono::milliseconds(60));
	reporter(Failure("boom"));  // a period has passed: the count of the repeats since
	reporter(Failure("boom"));
	reporter(Failure("boom"));
	EXPECT_EQ(lines.All().back(), boom + " (8 more times)");
	reports.Flush();  // the end: what is left
	EXPECT_EQ(lines.All().back(), boom + " (2 more times)");
	EXPECT_EQ(lines.All().size(), 6u);
	EXPECT_EQ(reports.Suppressed(), 10u);
	reports.Flush();
	EXPECT_EQ(lines.All().size(), 6u) << "nothing left to count";
}

TEST(RobotReports, AListenerSeesEveryReportWithItsRobot) {
	RobotReports reports(RobotReports::Limits{1, std::chrono::seconds(10)});
	reports.SetPrinter([](const std::string&) {});
	std::vector<std::string> heard;
	reports.SetListener([&](const RobotReport& report) { heard.push_back(report.robot + "/" + report.behaviour + "/" + report.report.text); });
	const auto reporter = reports.For("away-5", "Attacker");
	reporter(Failure("boom"));
	reporter(Failure("boom"));
	EXPECT_EQ(heard, (std::vector<std::string>{"away-5/Attacker/boom", "away-5/Attacker/boom"}));
}

TEST(RobotReports, AMatchNamesTheRobotInEveryLineAndCountsRepeatsAtItsEnd) {
	MatchConfig config;
	config.start_playing = true;
	config.home.players.push_back({"Thrower", 1, std::nullopt, {}});
	config.away.players.push_back({"Chaser", 1, std::nullopt, {}});
	Lines lines;
	Match match(config);
	match.Reports().SetPrinter(lines.Printer());
	match.Run(10);
	const std::string message =
	    "[home-1 Thrower] statechart 'Node_Throw': activity 'Throw' of state 0.2 'Node_Throw' threw: the ball is not where it should be";
	const auto all = lines.All();
	ASSERT_EQ(all.size(), 4u);
	for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(all[i], message);
	EXPECT_THAT(all[3], StartsWith(message + " ("));
	EXPECT_EQ(3 + std::stoul(all[3].substr(message.size() + 2)), match.Failures());
}

TEST(LogFile, WritesWholeLinesAtLeastEveryPeriod) {
	const std::string path = Scratch("period.jsonl");
	LogFile file(path, std::chrono::milliseconds(50));
	file.Append("{\"a\":1}\n");
	EXPECT_EQ(Read(path), "") << "buffered";
	std::this_thread::sleep_for(std::chrono::milliseconds(60));
	file.FlushIfDue();  // what a supervisor does while the match thread is busy
	EXPECT_EQ(Read(path), "{\"a\":1}\n");
	file.Append("{\"b\":2}\n");
	std::this_thread::sleep_for(std::chrono::milliseconds(60));
	file.Append("{\"c\":3}\n");  // an append after the period writes too
	EXPECT_EQ(Read(path), "{\"a\":1}\n{\"b\":2}\n{\"c\":3}\n");
}

TEST(LogFile, NeverWritesPartOfALine) {
	const std::string path = Scratch("whole.jsonl");
	LogFile file(path, std::chrono::hours(1), 64);
	const std::string line = "{\"frame\":\"" + std::string(20, 'x') + "\"}\n";  // 33 bytes: one fits, two do not
	for (int i = 0; i < 10; ++i) {
		file.Append(line);
		const std::string written = Read(path);
		EXPECT_EQ(written.size() % line.size(), 0u);
	}
	const std::string big = "{\"big\":\"" + std::string(200, 'y') + "\"}\n";  // more than the buffer
	file.Append(big);
	file.Flush();
	std::string expected;
	for (int i = 0; i < 10; ++i) expected += line;
	EXPECT_EQ(Read(path), expected + big);
	char tail[] = "{\"type\":\"aborted\"}\n";
	file.Append(line);
	file.FlushFromSignal(tail, sizeof tail - 1);
	EXPECT_EQ(Read(path), expected + big + line + tail);
}

TEST(LogFile, SaysWhenItCannotWrite) {
	EXPECT_THROW(LogFile("/nonexistent-directory/x.jsonl"), std::runtime_error);
}

TEST(JsonLinesLog, StreamsIntoAFileTheSameBytesAsIntoAStream) {
	MatchConfig config;
	config.seed = 11;
	config.start_playing = true;
	config.home.players.push_back({"Chaser", 1, std::nullopt, {}});
	config.away.players.push_back({"Chaser", 1, std::nullopt, {}});
	std::ostringstream text;
	{
		JsonLinesLog log(text);
		Match match(config);
		match.AddObserver(log);
		match.Run(20);
	}
	const std::string path = Scratch("stream.jsonl");
	{
		LogFile file(path);
		JsonLinesLog log(file);
		Match match(config);
		match.AddObserver(log);
		match.Run(20);
		EXPECT_EQ(log.LastCentiseconds(), 2000);
	}
	EXPECT_EQ(Read(path), text.str());
}

TEST(JsonLinesLog, AnAbortedLineEndsAMatchThatCouldNotEnd) {
	std::ostringstream text;
	JsonLinesLog log(text);
	log.Aborted("hang", "home-2", "Defender stuck for 5.0 s in the activity 'Scan' of state 0.2 'Node_Scan'");
	EXPECT_EQ(text.str(),
	          "{\"type\":\"aborted\",\"t\":0.00,\"reason\":\"hang\",\"robot\":\"home-2\",\"detail\":\"Defender stuck for 5.0 s in the activity "
	          "'Scan' of state 0.2 'Node_Scan'\"}\n");
	char line[256];
	const std::size_t length = JsonLinesLog::AbortedLine(line, sizeof line, 1234, "crash", "home-2", "SIGSEGV");
	EXPECT_EQ(std::string(line, length), "{\"type\":\"aborted\",\"t\":12.34,\"reason\":\"crash\",\"robot\":\"home-2\",\"detail\":\"SIGSEGV\"}\n");
	EXPECT_EQ(std::string(line, JsonLinesLog::AbortedLine(line, sizeof line, 5, "crash", nullptr, "SIGABRT")),
	          "{\"type\":\"aborted\",\"t\":0.05,\"reason\":\"crash\",\"detail\":\"SIGABRT\"}\n");
	EXPECT_EQ(JsonLinesLog::AbortedLine(line, 20, 5, "crash", nullptr, "SIGABRT"), 0u) << "does not fit";
}
