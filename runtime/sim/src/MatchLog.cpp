#include <kse/sim/MatchLog.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include <kse/robot/MonitorServer.h>

namespace kse::sim {

std::string JsonString(const std::string& text) {
	std::string out;
	robot::AppendJsonString(out, text);
	return out;
}

std::string Fixed(double value, int digits) {
	char text[64];
	std::snprintf(text, sizeof text, "%.*f", digits, value);
	std::string out = text;
	// "-0.000" and "0.000" are the same number; write it one way
	if (out[0] == '-' && out.find_first_not_of("-0.") == std::string::npos) out.erase(0, 1);
	return out;
}

namespace {

std::string Score(const Match& match) {
	const auto& score = match.GetReferee().Score();
	return "[" + std::to_string(score[0]) + "," + std::to_string(score[1]) + "]";
}

}  // namespace

std::string MatchRecordFields(const Match& match) {
	std::ostringstream line;
	const auto& config = match.Config();
	line << "\"version\":1,\"seed\":" << config.seed << ",\"tick\":" << Fixed(Match::kTick)
	     << ",\"field\":{\"length\":" << Fixed(2 * field::kHalfLength) << ",\"width\":" << Fixed(2 * field::kHalfWidth)
	     << ",\"goalWidth\":" << Fixed(2 * field::kGoalInnerHalfWidth) << "},\"halfSeconds\":" << Fixed(config.referee.half_seconds, 1)
	     << ",\"teams\":[";
	for (int team = 0; team < 2; ++team) {
		const TeamConfig& t = match.Team(team);
		line << (team ? "," : "") << "{\"number\":" << t.number << ",\"name\":" << JsonString(t.name) << ",\"players\":[";
		bool first = true;
		for (std::size_t i = 0; i < match.RobotCount(); ++i) {
			if (match.GetWorld().bodies[i].team != team) continue;
			line << (first ? "" : ",") << "{\"id\":" << JsonString(match.RobotId(i)) << ",\"number\":" << match.GetWorld().bodies[i].number
			     << ",\"behaviour\":" << JsonString(match.Behaviour(i)) << "}";
			first = false;
		}
		line << "]}";
	}
	line << "]";
	return line.str();
}

std::string EventRecord(const Match& match, const MatchEvent& event) {
	std::ostringstream line;
	line << "{\"type\":\"event\",\"t\":" << Fixed(event.time, 2) << ",\"event\":" << JsonString(event.type);
	if (event.team >= 0) line << ",\"team\":" << event.team;
	if (event.robot >= 0) line << ",\"robot\":" << JsonString(match.RobotId(static_cast<std::size_t>(event.robot)));
	if (!event.detail.empty()) line << ",\"detail\":" << JsonString(event.detail);
	line << "}";
	return line.str();
}

std::string ResultRecord(const Match& match) {
	std::ostringstream line;
	line << "{\"type\":\"result\",\"t\":" << Fixed(match.Time(), 2) << ",\"state\":\"" << ToString(match.GetReferee().State())
	     << "\",\"score\":" << Score(match) << ",\"stuck\":" << match.StuckCount() << ",\"failed\":" << match.FailedCount() << ",\"failures\":" << match.Failures() << "}";
	return line.str();
}

std::string AbortedRecord(double time, const std::string& reason, const std::string& robot, const std::string& detail) {
	std::ostringstream line;
	line << "{\"type\":\"aborted\",\"t\":" << Fixed(time, 2) << ",\"reason\":" << JsonString(reason);
	if (!robot.empty()) line << ",\"robot\":" << JsonString(robot);
	line << ",\"detail\":" << JsonString(detail) << "}";
	return line.str();
}

void JsonLinesLog::OnStart(const Match& match) {
	std::ostringstream line;
	line << "{\"type\":\"match\"," << MatchRecordFields(match) << "}";
	Write(line, 0);
}

void JsonLinesLog::OnFrame(const Match& match) {
	std::ostringstream line;
	const World& world = match.GetWorld();
	const Referee& referee = match.GetReferee();
	line << "{\"type\":\"frame\",\"t\":" << Fixed(match.Time(), 2) << ",\"state\":\"" << ToString(referee.State())
	     << "\",\"half\":" << referee.Half() << ",\"secs\":" << Fixed(referee.SecsRemaining(), 1) << ",\"score\":" << Score(match)
	     << ",\"ball\":[" << Fixed(world.ball.position.x) << "," << Fixed(world.ball.position.y) << "," << Fixed(world.ball.velocity.x)
	     << "," << Fixed(world.ball.velocity.y) << "],\"robots\":[";
	for (std::size_t i = 0; i < match.RobotCount(); ++i) {
		const Body& body = world.bodies[i];
		line << (i ? "," : "") << "{\"id\":" << JsonString(match.RobotId(i)) << ",\"pose\":[" << Fixed(body.pose.x) << ","
		     << Fixed(body.pose.y) << "," << Fixed(body.pose.theta) << "],\"head\":[" << Fixed(body.head_yaw) << ","
		     << Fixed(body.head_pitch) << "],\"motion\":\"" << ToString(body.motion) << "\",\"penalty\":" << referee.Penalty(static_cast<int>(i))
		     << ",\"ballSeen\":" << (match.LastPerception(i).ball.seen ? "true" : "false") << ",\"active\":[";
		const auto active = match.ActiveStates(i);
		for (std::size_t s = 0; s < active.size(); ++s) line << (s ? "," : "") << JsonString(active[s]);
		line << "],\"taken\":[";
		const auto& taken = match.TransitionsSinceFrame(i);
		for (std::size_t s = 0; s < taken.size(); ++s) line << (s ? "," : "") << JsonString(*taken[s]);
		line << "]}";
	}
	line << "]}";
	Write(line, match.Time());
}

void JsonLinesLog::OnEvent(const Match& match, const MatchEvent& event) {
	std::ostringstream line;
	line << EventRecord(match, event);
	Write(line, event.time);
}

void JsonLinesLog::OnEnd(const Match& match) {
	std::ostringstream line;
	line << ResultRecord(match);
	Write(line, match.Time());
	if (file_) file_->Flush();
	if (out_) out_->flush();
}

void JsonLinesLog::Write(const std::ostringstream& line, double time) {
	std::string text = line.str();
	text += '\n';
	if (file_) file_->Append(text);
	if (out_) *out_ << text;
	last_centiseconds_.store(std::llround(time * 100), std::memory_order_relaxed);
}

void JsonLinesLog::Aborted(const std::string& reason, const std::string& robot, const std::string& detail) {
	const double time = static_cast<double>(LastCentiseconds()) / 100;
	std::ostringstream line;
	line << AbortedRecord(time, reason, robot, detail);
	Write(line, time);
	if (file_) file_->Flush();
	if (out_) out_->flush();
}

std::size_t JsonLinesLog::AbortedLine(char* out, std::size_t size, std::int64_t centiseconds, const char* reason, const char* robot,
                                      const char* detail) noexcept {
	std::size_t used = 0;
	bool fits = true;
	auto add = [&](const char* text, bool quoted) {
		for (; *text != '\0'; ++text) {
			// ids and signal names need no escapes; anything that would is left out
			if (quoted && (*text == '"' || *text == '\\' || static_cast<unsigned char>(*text) < 0x20)) continue;
			if (used + 1 >= size) {
				fits = false;
				return;
			}
			out[used++] = *text;
		}
	};
	auto add_string = [&](const char* text) {
		add("\"", false);
		add(text, true);
		add("\"", false);
	};
	char number[32];
	std::size_t digits = 0;
	std::int64_t value = centiseconds < 0 ? 0 : centiseconds;
	do {
		number[digits++] = static_cast<char>('0' + value % 10);
		value /= 10;
	} while (value > 0 || digits < 3);
	char time[36];
	std::size_t length = 0;
	for (std::size_t i = digits; i-- > 0;) {
		time[length++] = number[i];
		if (i == 2) time[length++] = '.';
	}
	time[length] = '\0';
	add("{\"type\":\"aborted\",\"t\":", false);
	add(time, false);
	add(",\"reason\":", false);
	add_string(reason);
	if (robot != nullptr) {
		add(",\"robot\":", false);
		add_string(robot);
	}
	add(",\"detail\":", false);
	add_string(detail);
	add("}\n", false);
	return fits ? used : 0;
}

// ---------------------------------------------------------------------------------------------

namespace {

constexpr double kScale = 60;  // pixels a metre
constexpr double kMargin = 0.3;
const char* const kTeamColours[] = {"#1f5fd6", "#d62f2f"};

double Px(double x) { return (x + field::kCarpetHalfLength) * kScale; }
double Py(double y) { return (field::kCarpetHalfWidth - y) * kScale; }  // SVG y grows downwards
std::string P(Vec2 point) { return Fixed(Px(point.x), 1) + "," + Fixed(Py(point.y), 1); }

std::string Xml(const std::string& text) {
	std::string out;
	for (const char c : text) {
		switch (c) {
			case '<': out += "&lt;"; break;
			case '>': out += "&gt;"; break;
			case '&': out += "&amp;"; break;
			case '"': out += "&quot;"; break;
			default: out += c;
		}
	}
	return out;
}

}  // namespace

void SvgPicture::OnStart(const Match& match) {
	robots_.clear();
	for (std::size_t i = 0; i < match.RobotCount(); ++i) {
		robots_.push_back({match.RobotId(i) + " " + match.Behaviour(i), match.GetWorld().bodies[i].team, {}, {}});
	}
	teams_ = {match.Team(0).name, match.Team(1).name};
	title_ = teams_[0] + " vs " + teams_[1] + ", seed " + std::to_string(match.Config().seed);
}

void SvgPicture::OnFrame(const Match& match) {
	// a point every half second is enough for a path; a match would otherwise make a huge file
	if (frames_++ % 5 != 0) return;
	const World& world = match.GetWorld();
	for (std::size_t i = 0; i < robots_.size() && i < world.bodies.size(); ++i) {
		Path& path = robots_[i];
		const Body& body = world.bodies[i];
		if (!body.on_field) {
			if (!path.pieces.empty() && !path.pieces.back().empty()) path.pieces.emplace_back();
			continue;
		}
		// no robot walks a metre in half a second: it was carried (penalty, placement)
		const bool carried = path.pieces.empty() || path.pieces.back().empty() || (body.pose.Position() - path.last).Norm() > 1.0;
		if (carried && (path.pieces.empty() || !path.pieces.back().empty())) path.pieces.emplace_back();
		path.pieces.back().push_back(body.pose.Position());
		path.last = body.pose.Position();
	}
	ball_.push_back(world.ball.position);
}

void SvgPicture::OnEvent(const Match& match, const MatchEvent& event) {
	if (event.type == "goal") goals_.push_back({event.time, event.team, match.GetWorld().ball.position, event.detail});
}

void SvgPicture::OnEnd(const Match& match) {
	const auto& score = match.GetReferee().Score();
	result_ = teams_[0] + " " + std::to_string(score[0]) + " : " + std::to_string(score[1]) + " " + teams_[1] + " after " +
	          Fixed(match.Time(), 1) + " s";
}

void SvgPicture::Write(std::ostream& out) const {
	using namespace field;
	const double width = 2 * kCarpetHalfLength * kScale;
	const double height = 2 * kCarpetHalfWidth * kScale + 40;
	out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << Fixed(width, 0) << "\" height=\"" << Fixed(height, 0)
	    << "\" viewBox=\"0 0 " << Fixed(width, 0) << " " << Fixed(height, 0) << "\" font-family=\"sans-serif\">\n";
	out << "<title>" << Xml(title_) << "</title>\n";
	out << "<rect width=\"100%\" height=\"100%\" fill=\"#2e8b3a\"/>\n";
	// lines
	out << "<g fill=\"none\" stroke=\"white\" stroke-width=\"" << Fixed(kLineWidth * kScale, 1) << "\">\n";
	out << "<rect x=\"" << Fixed(Px(-kHalfLength), 1) << "\" y=\"" << Fixed(Py(kHalfWidth), 1) << "\" width=\""
	    << Fixed(2 * kHalfLength * kScale, 1) << "\" height=\"" << Fixed(2 * kHalfWidth * kScale, 1) << "\"/>\n";
	out << "<line x1=\"" << Fixed(Px(0), 1) << "\" y1=\"" << Fixed(Py(kHalfWidth), 1) << "\" x2=\"" << Fixed(Px(0), 1) << "\" y2=\""
	    << Fixed(Py(-kHalfWidth), 1) << "\"/>\n";
	out << "<circle cx=\"" << Fixed(Px(0), 1) << "\" cy=\"" << Fixed(Py(0), 1) << "\" r=\"" << Fixed(kCentreCircleRadius * kScale, 1) << "\"/>\n";
	for (int side : {-1, 1}) {
		for (const auto& area : {std::pair<double, double>{kPenaltyAreaLength, kPenaltyAreaWidth}, {kGoalAreaLength, kGoalAreaWidth}}) {
			const double x0 = side > 0 ? kHalfLength - area.first : -kHalfLength;
			out << "<rect x=\"" << Fixed(Px(x0), 1) << "\" y=\"" << Fixed(Py(area.second / 2), 1) << "\" width=\""
			    << Fixed(area.first * kScale, 1) << "\" height=\"" << Fixed(area.second * kScale, 1) << "\"/>\n";
		}
		const double mark = side * (kHalfLength - kPenaltyMarkDistance);
		out << "<line x1=\"" << Fixed(Px(mark - 0.05), 1) << "\" y1=\"" << Fixed(Py(0), 1) << "\" x2=\"" << Fixed(Px(mark + 0.05), 1)
		    << "\" y2=\"" << Fixed(Py(0), 1) << "\"/>\n";
	}
	out << "</g>\n";
	// goals: posts and nets
	for (int side : {-1, 1}) {
		const double back = side * (kPostX + kGoalDepth);
		out << "<polyline fill=\"#dddddd\" fill-opacity=\"0.4\" stroke=\"#cccccc\" stroke-width=\"2\" points=\"" << P({side * kPostX, kPostY})
		    << " " << P({back, kPostY}) << " " << P({back, -kPostY}) << " " << P({side * kPostX, -kPostY}) << "\"/>\n";
		for (int post : {-1, 1}) {
			out << "<circle cx=\"" << Fixed(Px(side * kPostX), 1) << "\" cy=\"" << Fixed(Py(post * kPostY), 1) << "\" r=\""
			    << Fixed(kPostRadius * kScale, 1) << "\" fill=\"white\" stroke=\"black\"/>\n";
		}
	}
	// paths
	for (const auto& robot : robots_) {
		if (robot.pieces.empty() || robot.pieces.front().empty()) continue;
		const char* colour = kTeamColours[robot.team];
		out << "<path fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\" stroke-opacity=\"0.7\" d=\"";
		for (const auto& piece : robot.pieces) {
			for (std::size_t i = 0; i < piece.size(); ++i) out << (i ? " L" : " M") << P(piece[i]);
		}
		out << "\"/>\n";
		const Vec2 last = robot.last;
		out << "<circle cx=\"" << Fixed(Px(last.x), 1) << "\" cy=\"" << Fixed(Py(last.y), 1) << "\" r=\"" << Fixed(nao::kBodyRadius * kScale, 1)
		    << "\" fill=\"" << colour << "\" stroke=\"black\"/>\n";
		out << "<text x=\"" << Fixed(Px(last.x) + 10, 1) << "\" y=\"" << Fixed(Py(last.y) - 10, 1) << "\" font-size=\"12\" fill=\"white\">"
		    << Xml(robot.id) << "</text>\n";
	}
	if (!ball_.empty()) {
		out << "<polyline fill=\"none\" stroke=\"#ff9900\" stroke-width=\"1.5\" stroke-dasharray=\"4 3\" points=\"";
		for (std::size_t i = 0; i < ball_.size(); ++i) out << (i ? " " : "") << P(ball_[i]);
		out << "\"/>\n";
		out << "<circle cx=\"" << Fixed(Px(ball_.back().x), 1) << "\" cy=\"" << Fixed(Py(ball_.back().y), 1) << "\" r=\""
		    << Fixed(kBallRadius * kScale * 1.5, 1) << "\" fill=\"#ff9900\" stroke=\"black\"/>\n";
	}
	for (const auto& goal : goals_) {
		out << "<circle cx=\"" << Fixed(Px(goal.where.x), 1) << "\" cy=\"" << Fixed(Py(goal.where.y), 1)
		    << "\" r=\"9\" fill=\"none\" stroke=\"yellow\" stroke-width=\"3\"/>\n";
		// the label goes towards the field, away from the goal line
		out << "<text x=\"" << Fixed(Px(goal.where.x) + (goal.where.x > 0 ? -14 : 14), 1) << "\" y=\"" << Fixed(Py(goal.where.y) + 24, 1)
		    << "\" text-anchor=\"" << (goal.where.x > 0 ? "end" : "start") << "\" font-size=\"13\" fill=\"yellow\">goal " << goal.score
		    << " at " << Fixed(goal.time, 0) << " s</text>\n";
	}
	out << "<text x=\"10\" y=\"" << Fixed(height - 14, 0) << "\" font-size=\"18\" fill=\"white\">" << Xml(title_) << ": " << Xml(result_) << "</text>\n";
	out << "</svg>\n";
}

}  // namespace kse::sim
