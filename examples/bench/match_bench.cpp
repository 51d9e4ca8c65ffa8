// How fast the simulator plays: a 5-against-5 ten-minute half of the example behaviours on one
// core, its real-time factor, the share of the time spent in the robots' statecharts, and the
// same match with scripted players (no statecharts) as the baseline measured in this run.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <kse/sim/Match.h>

using namespace kse::sim;

namespace {

PlayerConfig Player(const std::string& behaviour, int number) { return {behaviour, number, std::nullopt, {}}; }

// A scripted player: walks at the ball and kicks, or to its kick-off pose outside PLAYING.
kse::robot::MotionCommands Scripted(const kse::robot::Perception& p) {
	kse::robot::MotionCommands commands;
	commands.walk = true;
	commands.head = true;
	commands.pitch = 0.3f;
	if (p.player_state == 3 && p.ball.seen) {
		commands.vx = std::clamp(3 * (p.ball.x - 0.13f), -1.0f, 1.0f);
		commands.vy = std::clamp(3 * (p.ball.y - 0.04f), -1.0f, 1.0f);
		commands.vtheta = std::atan2(p.ball.y, p.ball.x);
		if (std::hypot(p.ball.x - 0.13f, p.ball.y - 0.04f) < 0.04f) commands.actions.push_back("KickForwardLeft");
	} else if (p.player_state == 3) {
		commands.vtheta = 0.5f;
	} else if (p.player_state == 1) {
		commands.vx = std::clamp(p.ready_position.x - p.estimate.x, -1.0f, 1.0f);
		commands.vy = std::clamp(p.ready_position.y - p.estimate.y, -1.0f, 1.0f);
	}
	return commands;
}

MatchConfig FiveAgainstFive(std::uint64_t seed, bool scripted) {
	MatchConfig config;
	config.seed = seed;
	config.home.players = {Player("Goalie", 1), Player("Defender", 2), Player("Defender", 3), Player("Attacker", 4), Player("Attacker", 5)};
	config.away.players = config.home.players;
	if (scripted) {
		for (auto* team : {&config.home, &config.away}) {
			for (auto& player : team->players) player.controller = Scripted;
		}
	}
	return config;
}

struct Figures {
	double simulated = 0;
	double wall = 0;
	double engine = 0;
};

Figures Play(std::uint64_t seed, bool scripted) {
	Match match(FiveAgainstFive(seed, scripted));
	const auto start = std::chrono::steady_clock::now();
	match.Run(0);
	Figures figures;
	figures.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	figures.simulated = match.Time();
	figures.engine = match.EngineSeconds();
	return figures;
}

}  // namespace

int main(int argc, char** argv) {
	const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
	std::vector<double> factors, shares, baselines;
	for (int run = 0; run < runs; ++run) {
		const Figures figures = Play(static_cast<std::uint64_t>(run + 1), false);
		const Figures baseline = Play(static_cast<std::uint64_t>(run + 1), true);
		factors.push_back(figures.simulated / figures.wall);
		shares.push_back(figures.engine / figures.wall);
		baselines.push_back(baseline.simulated / baseline.wall);
		std::printf("run %d: %.0f s simulated in %.2f s (real-time factor %.0fx, statecharts %.0f%% of the time); scripted players: %.0fx\n",
		            run + 1, figures.simulated, figures.wall, factors.back(), 100 * shares.back(), baselines.back());
	}
	auto median = [](std::vector<double> values) {
		std::sort(values.begin(), values.end());
		return values[values.size() / 2];
	};
	const double factor = median(factors);
	const double share = median(shares);
	const double baseline = median(baselines);
	// The goals of issue 17, item 5, and what was measured before the work on it (and the share
	// before its last round, runtime/README.md), printed with today's figures so that one run
	// gives before and after; only a factor under 200 fails.
	std::printf("5 vs 5 example behaviours, 10-minute half, one core, median of %d: real-time factor %.0fx "
	            "(goal >= 1500x; before: 969x), statecharts %.0f%% of the time (goal <= 25%%; before: 53%%, "
	            "26-28%% before the last round); "
	            "baseline in this run, scripted players without statecharts: %.0fx (ratio %.2f)\n",
	            runs, factor, 100 * share, baseline, baseline / factor);
	return factor >= 200 ? 0 : 1;
}
