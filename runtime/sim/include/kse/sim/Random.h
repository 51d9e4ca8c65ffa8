#pragma once
// The simulation's only source of chance. Its own generator and Gaussian (not <random>'s
// distributions, whose algorithms differ between standard libraries), so a seed gives the
// same match on every machine with the same binary.

#include <cmath>
#include <cstdint>

namespace kse::sim {

class Random {
public:
	explicit Random(std::uint64_t seed) {
		// splitmix64 spreads any seed (0 included) over the four words of xoshiro256**
		for (auto& word : state_) {
			seed += 0x9E3779B97F4A7C15ULL;
			std::uint64_t z = seed;
			z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
			z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
			word = z ^ (z >> 31);
		}
	}

	std::uint64_t Next() {
		const std::uint64_t result = Rotl(state_[1] * 5, 7) * 9;
		const std::uint64_t t = state_[1] << 17;
		state_[2] ^= state_[0];
		state_[3] ^= state_[1];
		state_[1] ^= state_[2];
		state_[0] ^= state_[3];
		state_[2] ^= t;
		state_[3] = Rotl(state_[3], 45);
		return result;
	}

	/** Uniform in [0, 1). */
	double Uniform() { return static_cast<double>(Next() >> 11) * 0x1.0p-53; }
	double Uniform(double low, double high) { return low + (high - low) * Uniform(); }
	bool Chance(double probability) { return Uniform() < probability; }

	/** Normal with mean 0 and the given standard deviation (Box-Muller, one value per call). */
	double Gaussian(double sigma) {
		double u = Uniform();
		while (u <= 1e-300) u = Uniform();
		const double v = Uniform();
		return sigma * std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * 3.14159265358979323846 * v);
	}

	/** An independent generator for one part of the simulation, so adding draws in one part leaves the others unchanged. */
	Random Fork() { return Random(Next()); }

private:
	static std::uint64_t Rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
	std::uint64_t state_[4]{};
};

}  // namespace kse::sim
