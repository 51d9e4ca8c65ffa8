// main() of kse-match: link this (kse::sim_main) with the behaviours to play.
#include <iostream>

#include <kse/sim/MatchCli.h>
#include <statechart_engine/Factories.h>

int main(int argc, char** argv) {
	// Two activities (or statecharts) of one name linked into one program: a statechart would run
	// whichever the linker registered first. Stop before playing, naming both (ADR 0029).
	auto clashes = statechart_engine::ActivityFactory::Instance().Clashes();
	for (const auto& clash : statechart_engine::StatechartFactory::Instance().Clashes()) clashes.push_back(clash);
	if (!clashes.empty()) {
		for (const auto& clash : clashes) std::cerr << "kse-match: error: " << clash << "\n";
		std::cerr << "kse-match: names are global in one program: rename one (its formula, its folder under "
		             "src/activities and its registrar) and build again\n";
		return 2;
	}
	return kse::sim::RunMatchCli(argc, argv);
}
