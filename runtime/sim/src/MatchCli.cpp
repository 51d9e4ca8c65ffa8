#include <kse/sim/MatchCli.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include <statechart_engine/Factories.h>
#include <kse/sim/GameControllerLink.h>
#include <kse/sim/LogFile.h>
#include <kse/sim/MatchDiscovery.h>
#include <kse/sim/MatchLog.h>
#include <kse/sim/MatchMonitor.h>
#include <kse/sim/MatchSupervisor.h>

namespace kse::sim {

namespace {

constexpr const char* kUsage = R"(usage: kse-match [options]
Plays a simulated RoboCup SPL match between the registered behaviours of this program.

  --home LIST        home team: Behaviour[:number],... (default Goalie:1,Defender:2,Attacker:3)
  --away LIST        away team, the same way; "none" for no team (default as home)
  --seed N           seed of the simulation (default 1); a seed always gives the same match
  --half SECONDS     PLAYING seconds of a half (default 600)
  --halves N         1 or 2 (default 1)
  --duration SECONDS stop after this much simulated time (default: when the game is FINISHED)
  --start-playing    skip INITIAL, READY and SET: start at the kick-off in PLAYING
  --log FILE         write the JSON-lines log of the match, as it runs (whole lines, at least every
                     second: after a crash, a hang or Ctrl+C it holds the match up to then)
  --svg FILE         write a picture of the match
  --realtime         run at real speed (to watch it) instead of as fast as possible; --speed 1
  --speed F          run at F times real speed (0.01 to 1000; e.g. 10: a 10 min half in 1 min)
  --monitor          let a live monitor watch the match (docs/monitor.md): listens on 127.0.0.1,
                     on a port the system chooses, and prints before the start
                     "kse-match: monitor on 127.0.0.1:PORT token TOKEN" on standard error; it
                     announces itself to kse serve and the workbench in the user's private folder
                     $XDG_RUNTIME_DIR/kse/matches (or ~/.cache/kse/matches) while it runs
  --monitor-port N   the same on port N
  --monitor-wait     with --monitor: start the match only once a monitor client has subscribed
                     (at most 60 s, then it starts anyway)
  --monitor-watchers N  the same, once N clients have subscribed (a board of N robots sees
                     every robot from the kick-off)
  --hang-limit SECONDS  end the match (exit status 3) when a robot's behaviour has been in one
                     call this long (default 5; 0: wait forever); the engine's watchdog names
                     the call after 1 s
  --gamecontroller   follow a real GameController (UDP 3838 on loopback) and answer on 3939,
                     the whole game: it ends when the game is over, not at one FINISHED
  --home-number N, --away-number N   team numbers (default 7 and 8); with --gamecontroller,
                     the numbers of the teams set in the GameController
  --list             list the behaviours this program can play
  --quiet            no progress lines
  --help
)";

struct UsageError : std::runtime_error {
	using std::runtime_error::runtime_error;
};

std::vector<PlayerConfig> ParseTeam(const std::string& text) {
	std::vector<PlayerConfig> players;
	if (text == "none") return players;
	std::stringstream list(text);
	std::string item;
	int next_number = 1;
	while (std::getline(list, item, ',')) {
		if (item.empty()) throw UsageError("empty player in '" + text + "'");
		PlayerConfig player;
		const auto colon = item.find(':');
		player.behaviour = item.substr(0, colon);
		player.number = next_number;
		if (colon != std::string::npos) {
			const std::string number = item.substr(colon + 1);
			char* end = nullptr;
			const long value = std::strtol(number.c_str(), &end, 10);
			if (number.empty() || *end != '\0' || value < 1 || value > 20) {
				throw UsageError("player number must be 1 to 20 in '" + item + "'");
			}
			player.number = static_cast<int>(value);
		}
		for (const auto& other : players) {
			if (other.number == player.number) throw UsageError("two players with number " + std::to_string(player.number) + " in '" + text + "'");
		}
		const auto names = statechart_engine::StatechartFactory::Instance().Names();
		if (std::find(names.begin(), names.end(), player.behaviour) == names.end()) {
			std::string known;
			for (const auto& name : names) known += (known.empty() ? "" : ", ") + name;
			throw UsageError("no behaviour '" + player.behaviour + "' in this program (it has: " + known + ")");
		}
		next_number = player.number + 1;
		players.push_back(player);
	}
	if (players.size() > 7) throw UsageError("at most 7 players a team");
	return players;
}

double ParseNumber(const std::string& option, const std::string& text, double low, double high) {
	char* end = nullptr;
	const double value = std::strtod(text.c_str(), &end);
	if (text.empty() || *end != '\0' || !(value >= low && value <= high)) {
		throw UsageError(option + " needs a number from " + Fixed(low, 0) + " to " + Fixed(high, 0) + ", not '" + text + "'");
	}
	return value;
}

/** Says at once, even with --quiet, what following a GameController noticed (team numbers, ignored packets, silence). */
class GameControllerNotices : public MatchObserver {
public:
	void OnEvent(const Match&, const MatchEvent& event) override {
		if (event.type == "gamecontroller") std::cerr << "kse-match: " << event.detail << "\n";
	}
};

/** Writes a file whole or not at all: to a temporary name first, then renamed. */
void WriteAtomically(const std::string& path, const std::string& content) {
	const std::string temporary = path + ".tmp";
	{
		std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
		if (!out) throw std::runtime_error("cannot write " + path);
		out << content;
		if (!out.flush()) throw std::runtime_error("cannot write " + path);
	}
	if (std::rename(temporary.c_str(), path.c_str()) != 0) throw std::runtime_error("cannot write " + path);
}

}  // namespace

int RunMatchCli(int argc, char** argv) {
	MatchConfig config;
	std::string home = "Goalie:1,Defender:2,Attacker:3";
	std::string away;
	std::string log_path, svg_path;
	double duration = 0;
	double hang_limit = 5;
	double speed = 0;  // 0: as fast as it can
	bool quiet = false, gamecontroller = false;
	bool monitor = false, monitor_wait = false;
	std::size_t monitor_watchers = 1;
	int monitor_port = 0;
	try {
		for (int i = 1; i < argc; ++i) {
			const std::string option = argv[i];
			auto value = [&]() -> std::string {
				if (i + 1 >= argc) throw UsageError(option + " needs a value");
				return argv[++i];
			};
			if (option == "--help" || option == "-h") {
				std::cout << kUsage;
				return 0;
			} else if (option == "--list") {
				for (const auto& name : statechart_engine::StatechartFactory::Instance().Names()) std::cout << name << "\n";
				return 0;
			} else if (option == "--home") {
				home = value();
			} else if (option == "--away") {
				away = value();
			} else if (option == "--seed") {
				config.seed = static_cast<std::uint64_t>(ParseNumber(option, value(), 0, 1e15));
			} else if (option == "--half") {
				config.referee.half_seconds = ParseNumber(option, value(), 1, 3600);
			} else if (option == "--halves") {
				config.referee.halves = static_cast<int>(ParseNumber(option, value(), 1, 2));
			} else if (option == "--duration") {
				duration = ParseNumber(option, value(), 0.01, 36000);
			} else if (option == "--start-playing") {
				config.start_playing = true;
			} else if (option == "--log") {
				log_path = value();
			} else if (option == "--svg") {
				svg_path = value();
			} else if (option == "--hang-limit") {
				hang_limit = ParseNumber(option, value(), 0, 3600);
			} else if (option == "--realtime") {
				speed = 1;
			} else if (option == "--speed") {
				speed = ParseNumber(option, value(), 0.01, 1000);
			} else if (option == "--monitor") {
				monitor = true;
			} else if (option == "--monitor-port") {
				monitor = true;
				monitor_port = static_cast<int>(ParseNumber(option, value(), 1, 65535));
			} else if (option == "--monitor-wait") {
				monitor_wait = true;
			} else if (option == "--monitor-watchers") {
				monitor_wait = true;
				monitor_watchers = static_cast<std::size_t>(ParseNumber(option, value(), 1, 16));
			} else if (option == "--gamecontroller") {
				gamecontroller = true;
			} else if (option == "--home-number") {
				config.home.number = static_cast<int>(ParseNumber(option, value(), 1, 255));
			} else if (option == "--away-number") {
				config.away.number = static_cast<int>(ParseNumber(option, value(), 1, 255));
			} else if (option == "--quiet" || option == "-q") {
				quiet = true;
			} else {
				throw UsageError("unknown option '" + option + "'");
			}
		}
		config.home.players = ParseTeam(home);
		config.away.players = ParseTeam(away.empty() ? home : away);
		if (config.home.players.empty() && config.away.players.empty()) throw UsageError("both teams are empty");
		if (config.home.number == config.away.number) throw UsageError("the teams need different numbers");
		if (monitor_wait && !monitor) throw UsageError("--monitor-wait and --monitor-watchers need --monitor or --monitor-port");
	} catch (const UsageError& error) {
		std::cerr << "kse-match: " << error.what() << "\n" << kUsage;
		return 2;
	}
	config.home.name = "home";
	config.away.name = "away";

	try {
		std::unique_ptr<gc::GameControllerLink> link;
		// The log is streamed, and the supervisor comes before the match: its signal mask must
		// reach every thread the match starts.
		std::unique_ptr<LogFile> log_file;
		std::unique_ptr<JsonLinesLog> log;
		if (!log_path.empty()) {
			log_file = std::make_unique<LogFile>(log_path);
			log = std::make_unique<JsonLinesLog>(*log_file);
		}
		MatchSupervisor supervisor({std::chrono::milliseconds(std::llround(hang_limit * 1000))}, log_file.get(), log.get());
		Match match(config);
		match.Reports().SetListener([&supervisor](const RobotReport& report) { supervisor.OnReport(report); });
		SvgPicture picture;
		GameControllerNotices notices;
		if (log) match.AddObserver(*log);
		if (!svg_path.empty()) match.AddObserver(picture);
		if (gamecontroller) {
			link = std::make_unique<gc::GameControllerLink>(gc::GameControllerLink::Options{});
			match.Listen(*link);
			match.AddObserver(notices);
			speed = 1;  // a GameController runs in real time
			if (!quiet) {
				std::cerr << "kse-match: following the GameController on 127.0.0.1:" << link->ListenPort() << " as teams " << config.home.number
				          << " (home) and " << config.away.number << " (away)\n";
			}
		}
		// Made after the link and the other observers: it sees every event they cause. It only
		// reads the match, so the log is the same with it.
		std::unique_ptr<MatchMonitor> watcher;
		struct Unhook {
			MatchSupervisor* supervisor = nullptr;
			~Unhook() {
				if (supervisor) supervisor->OnAbort({});  // before the monitor goes: the supervisor outlives it
			}
		} unhook;
		// after the monitor: removed first when the match ends, so pickers stop listing it while
		// the monitor still hands its watchers the last lines
		std::unique_ptr<MatchAnnouncement> announcement;
		struct Unannounce {
			MatchSupervisor& supervisor;
			std::unique_ptr<MatchAnnouncement>& announcement;
			~Unannounce() {
				supervisor.RemoveAtExit({});
				announcement.reset();
			}
		} unannounce{supervisor, announcement};
		if (monitor) {
			robot::MonitorServer::Options options;
			options.port = static_cast<std::uint16_t>(monitor_port);
			options.notice = [](const std::string& line) { std::cerr << "kse-match: monitor: " << line << "\n"; };
			watcher = std::make_unique<MatchMonitor>(match, options);
			match.AddObserver(*watcher);
			MatchMonitor* raw = watcher.get();
			supervisor.OnAbort([raw](const std::string& reason, const std::string& robot, const std::string& detail) { raw->Aborted(reason, robot, detail); });
			unhook.supervisor = &supervisor;
			// even with --quiet: without it nobody can connect
			std::cerr << "kse-match: " << watcher->Server().Address() << std::endl;
			// so that kse serve and the workbench can list it; a match that cannot be announced is
			// still watched by port and key
			try {
				announcement = std::make_unique<MatchAnnouncement>(
					DiscoveryFolder(), AnnouncementJson(match, static_cast<long>(::getpid()), watcher->Server().Port(), watcher->Server().Token(), robot::WallMilliseconds()));
				supervisor.RemoveAtExit(announcement->Path());
			} catch (const std::exception& error) {
				std::cerr << "kse-match: monitor: " << error.what() << " (connect with the port and the token above)" << std::endl;
			}
			if (monitor_wait && !watcher->WaitForSubscribers(monitor_watchers, std::chrono::seconds(60))) {
				std::cerr << "kse-match: " << (monitor_watchers == 1 ? std::string("no monitor client")
				                                                      : "fewer than " + std::to_string(monitor_watchers) + " monitor clients")
				          << " subscribed within 60 s; the match starts anyway" << std::endl;
			}
		}
		const auto wall_start = std::chrono::steady_clock::now();
		const bool paced = speed > 0;
		// a progress line every 5 s of wall time when paced
		const double report_every = paced ? 5 * speed : 60;
		double next_report = report_every;
		match.Run(duration, [&](const Match& m) {
			if (quiet || m.Time() < next_report) return;
			next_report = m.Time() + report_every;
			const auto& score = m.GetReferee().Score();
			std::cerr << "  " << Fixed(m.Time(), 0) << " s  " << ToString(m.GetReferee().State()) << "  " << score[0] << ":" << score[1]
			          << "  " << Fixed(m.GetReferee().SecsRemaining(), 0) << " s left\n";
		}, speed);
		const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
		if (!svg_path.empty()) {
			std::ostringstream svg;
			picture.Write(svg);
			WriteAtomically(svg_path, svg.str());
		}
		const auto& score = match.GetReferee().Score();
		std::cout << config.home.name << " " << score[0] << " : " << score[1] << " " << config.away.name << " after " << Fixed(match.Time(), 1)
		          << " s (seed " << config.seed << ", " << ToString(match.GetReferee().State()) << ")\n";
		for (const auto& event : match.Events()) {
			if (event.type == "goal") std::cout << "  goal at " << Fixed(event.time, 1) << " s by " << (event.robot >= 0 ? match.RobotId(static_cast<std::size_t>(event.robot)) : "?") << "\n";
			if (event.type == "failed" && event.robot >= 0) {
				const auto robot = static_cast<std::size_t>(event.robot);
				std::cout << "  " << match.RobotId(robot) << " " << match.Behaviour(robot) << " failed at " << Fixed(event.time, 1) << " s and stood still: " << event.detail << "\n";
			}
		}
		std::cout << "  stuck robots: " << match.StuckCount() << ", failed robots: " << match.FailedCount() << ", behaviour failures: " << match.Failures()
		          << ", real-time factor: " << Fixed(match.Time() / std::max(wall, 1e-9), 0) << "x\n";
		if (!log_path.empty()) std::cout << "  log: " << log_path << "\n";
		if (!svg_path.empty()) std::cout << "  picture: " << svg_path << "\n";
		return match.Failures() == 0 && match.FailedCount() == 0 ? 0 : 1;
	} catch (const std::exception& error) {
		std::cerr << "kse-match: " << error.what() << "\n";
		return 2;
	}
}

}  // namespace kse::sim
