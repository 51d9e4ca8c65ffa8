#pragma once
// What a match leaves behind for people and tools: a JSON-lines log (the input of the live
// monitor and of replays; format in docs/match-log.md) and an SVG picture of the match.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include <kse/sim/LogFile.h>
#include <kse/sim/Match.h>

namespace kse::sim {

/**
 * One JSON object a line: "match" (teams, seed, field), then "frame" lines (time, game state,
 * score, ball, every robot's pose, motion, active states and the transitions taken since the
 * previous frame) and "event" lines in time order, and a final "result" (or "aborted" when the
 * match could not end). Numbers are written with fixed precision, so a seed gives the same bytes.
 */
class JsonLinesLog : public MatchObserver {
public:
	explicit JsonLinesLog(std::ostream& out) : out_(&out) {}
	/** Streams the log into a file as the match runs (whole lines, written at least every second). */
	explicit JsonLinesLog(LogFile& file) : file_(&file) {}
	void OnStart(const Match& match) override;
	void OnFrame(const Match& match) override;
	void OnEvent(const Match& match, const MatchEvent& event) override;
	void OnEnd(const Match& match) override;

	/**
	 * The last line of a match that cannot end normally: {@code reason} "hang" (with the robot's
	 * id), "signal" or "crash"; written to the file at once. Any thread.
	 */
	void Aborted(const std::string& reason, const std::string& robot, const std::string& detail);
	/** The simulated time of the last line written, in hundredths of a second (any thread, a signal handler too). */
	std::int64_t LastCentiseconds() const noexcept { return last_centiseconds_.load(std::memory_order_relaxed); }
	/** The "aborted" line, as Aborted() writes it, for a signal handler (no allocation; {@code robot} may be null): its length, or 0 when it does not fit. */
	static std::size_t AbortedLine(char* out, std::size_t size, std::int64_t centiseconds, const char* reason, const char* robot,
	                               const char* detail) noexcept;

private:
	void Write(const std::ostringstream& line, double time);

	std::ostream* out_ = nullptr;
	LogFile* file_ = nullptr;
	std::atomic<std::int64_t> last_centiseconds_{0};
};

/** The field, every robot's path, the ball's path and the goals, as an SVG image. */
class SvgPicture : public MatchObserver {
public:
	void OnStart(const Match& match) override;
	void OnFrame(const Match& match) override;
	void OnEvent(const Match& match, const MatchEvent& event) override;
	void OnEnd(const Match& match) override;
	void Write(std::ostream& out) const;

private:
	struct Path {
		std::string id;
		int team = 0;
		std::vector<std::vector<Vec2>> pieces;  // a new piece after the robot was carried
		Vec2 last;
	};
	struct Goal {
		double time;
		int team;
		Vec2 where;
		std::string score;
	};
	std::vector<Path> robots_;
	std::vector<Vec2> ball_;
	std::vector<Goal> goals_;
	std::string title_;
	std::string result_;
	std::vector<std::string> teams_;
	int frames_ = 0;
};

// The records the log and the live monitor (MatchMonitor.h) both write, without '\n'.
/** The fields of the "match" record after its type: "version":1,...,"teams":[...]. */
std::string MatchRecordFields(const Match& match);
/** {"type":"event",...} */
std::string EventRecord(const Match& match, const MatchEvent& event);
/** {"type":"result",...}: the match as it ends. */
std::string ResultRecord(const Match& match);
/** {"type":"aborted",...}: a match that could not end ({@code robot} may be empty). */
std::string AbortedRecord(double time, const std::string& reason, const std::string& robot, const std::string& detail);

/** A JSON string literal (robot::AppendJsonString, the escaping the live monitor uses too). */
std::string JsonString(const std::string& text);
/** A number with {@code digits} decimals, "-0.000" written as "0.000". */
std::string Fixed(double value, int digits = 3);

}  // namespace kse::sim
