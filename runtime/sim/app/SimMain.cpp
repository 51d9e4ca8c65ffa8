// main() of kse-match: link this (kse::sim_main) with the behaviours to play.
#include <kse/sim/MatchCli.h>

int main(int argc, char** argv) { return kse::sim::RunMatchCli(argc, argv); }
