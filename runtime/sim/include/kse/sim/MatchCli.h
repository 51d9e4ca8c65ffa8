#pragma once
// The match runner's command line (kse-match): any program that links the behaviours it
// wants to play (their statecharts and activities register themselves) and kse::sim_main
// gets it as its main().

namespace kse::sim {

int RunMatchCli(int argc, char** argv);

}  // namespace kse::sim
