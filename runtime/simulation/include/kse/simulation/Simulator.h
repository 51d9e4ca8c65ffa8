#pragma once
// The simulator program, built once per set of statecharts (kse_add_simulator in
// KseBehavior.cmake links them in and calls this from its main):
//
//   <program> --activities A,B,... [--eager] --check <case>...   conformance: PASS/FAIL per case
//   <program> --activities A,B,... [--eager] --show <case>...    each case's actual trace
//   <program> --activities A,B,... --serve <Model>               a session: commands on standard
//                                                                input, one JSON line each on output
//
// The session's protocol is in docs/simulation.md.

namespace kse::simulation {

int RunSimulator(int argc, char** argv);

}  // namespace kse::simulation
