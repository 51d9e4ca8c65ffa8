package org.kse.cli;

import java.util.Map;

import org.kse.model.statechart.Model;

/**
 * The text of the files {@code kse new-behaviour} writes besides the formula and the model. The
 * activities follow the message contract of docs/robot-messages.md, as the examples' activities do
 * (examples/src/activities/common/RobotIO.h), and compile as written against the installed runtime.
 */
final class ProjectFiles {

	private ProjectFiles() {
	}

	/** The activities' namespace: the behaviour's name in lower case, so that two projects' helpers never meet. */
	static String namespace(String name) {
		return name.toLowerCase(java.util.Locale.ROOT);
	}

	static String cmake(String name) {
		String targets = NewBehaviour.rootName(name) + "_activities";
		return """
				# %1$s: a behaviour of your own, built against the installed KSE runtime and played against
				# the example behaviours (Goalie, Attacker, Defender). Made by `kse new-behaviour %1$s`;
				# README.md says how to build and play it.
				#
				# CMAKE_PREFIX_PATH must name the folder the KSE runtime and the examples are installed in
				# (`./kse demo` in a KSE clone installs both into <clone>/target/demo/runtime-prefix):
				#   cmake -S . -B build -DCMAKE_PREFIX_PATH=<prefix>
				# The build runs `kse generate` on %1$s.stct (kse_add_statechart): put the KSE clone on the
				# PATH (its ./kse), or pass -DKSE_EXECUTABLE=<clone>/kse.
				cmake_minimum_required(VERSION 3.20)
				project(%1$s LANGUAGES CXX)
				set(CMAKE_CXX_STANDARD 17)
				set(CMAKE_CXX_STANDARD_REQUIRED ON)
				if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
				  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
				endif()

				find_package(kse_runtime REQUIRED)   # kse::runtime, kse::sim_main, kse_add_statechart, kse_add_activities
				find_package(kse_examples REQUIRED)  # kse_examples::behaviours: the examples, to play against

				# The one convention: the statechart is generated from the model while building (into the
				# build tree, never into src/), the activities are the folders of src/activities, each with
				# the CMakeLists.txt that `kse generate %1$s.stct src --no-statechart` writes for a new one.
				# An activity named like one of the examples' stops the configuration (names are global
				# in one program).
				kse_add_statechart(%1$s %1$s.stct)
				kse_add_activities(%2$s src/activities)
				foreach(activity IN LISTS %2$s)
				  # every activity includes <common/Robot.h>, the helpers the activities share
				  target_include_directories(${activity} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src/activities)
				endforeach()

				# The simulated match with %1$s and the examples (kse::sim_main has main()); the statechart
				# and the activities are OBJECT libraries, linked here directly so that their registrars are.
				add_executable(kse-match)
				target_link_libraries(kse-match PRIVATE kse::sim_main statechart_%1$s ${%2$s} kse_examples::behaviours)
				""".formatted(name, targets);
	}

	static String activityCmake(String activity) {
		return """
				add_library(activity_%1$s OBJECT %1$s.cpp)
				target_include_directories(activity_%1$s PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
				target_link_libraries(activity_%1$s PUBLIC kse::runtime)
				""".formatted(activity);
	}

	static String activityHeader(String activity) {
		String state = activity.equals("Chase") ? "\n\nprivate:\n\tint _step = 0;  // where the head's sweep is" : "";
		return """
				#pragma once

				#include <string>

				#include <statechart_engine/Interfaces.h>

				/** The activity %1$s (see %1$s.cpp): yours, never overwritten by KSE. */
				class %1$s : public statechart_engine::IActivity {
				public:
					void UserInit() override;
					int Execute() override;
					std::string GetName() override { return "%1$s"; }%2$s
				};
				""".formatted(activity, state);
	}

	static String robotHeader(String name) {
		return """
				#pragma once
				// What the activities of %1$s share: reading the world and commanding the legs and the head,
				// by the message contract of the KSE docs (docs/robot-messages.md). The examples' activities
				// do the same, with kicks, dives and localisation, in examples/src/activities/common/RobotIO.h.

				#include <cmath>
				#include <memory>
				#include <string>

				#include <kse/behavior/BehaviorConst.h>
				#include <kse/messages/all.h>
				#include <kse/messaging/Blackboard.h>

				namespace %2$s {

				/** What an activity sees, read once per run. */
				struct World {
					std::shared_ptr<const GameStateMessage> game;  // worldstate, State: the game as the referee sees it
					std::shared_ptr<const WorldInfo> info;         // worldstate, Data: the ball (robot frame) and the robot's pose
					std::shared_ptr<const HeadToBMessage> head;    // behavior, State: whether the camera sees the ball

					/** Refreshes the blackboard first: it shows what was published up to its last refresh. */
					static World Read(kse::messaging::Blackboard& blackboard) {
						blackboard.ProcessMessages();
						World world;
						world.game = blackboard.ReadState<GameStateMessage>("worldstate");
						world.info = blackboard.ReadData<WorldInfo>("worldstate");
						world.head = blackboard.ReadState<HeadToBMessage>("behavior");
						return world;
					}

					bool Playing() const { return game && game->player_state() == PLAYER_PLAYING; }
					bool BallSeen() const { return head && head->ballfound() > 0 && info && info->balls_size() > 0; }
					/** Metres to the ball, and its bearing in radians (left positive); only while it is seen. */
					float BallDistance() const { return std::hypot(info->balls(0).relativex(), info->balls(0).relativey()); }
					float BallBearing() const { return std::atan2(info->balls(0).relativey(), info->balls(0).relativex()); }
				};

				/** An activity reads only the topics its blackboard subscribed to: call from UserInit. */
				inline void Subscribe(kse::messaging::Blackboard& blackboard) {
					blackboard.Subscribe("worldstate");
					blackboard.Subscribe("behavior");
				}

				inline float Clamp(float value) { return value < -1.0f ? -1.0f : value > 1.0f ? 1.0f : value; }

				/** Walk velocities, each in [-1, 1] of the walk's limits: forward, left, turning left. Lasts until the next command. */
				inline void Walk(kse::messaging::Blackboard& blackboard, float vx, float vy, float vtheta) {
					auto walk = std::make_shared<MotionWalkMessage>();
					walk->set_command("setWalkTargetVelocity");
					walk->add_parameter(Clamp(vx));
					walk->add_parameter(Clamp(vy));
					walk->add_parameter(Clamp(vtheta));
					walk->add_parameter(1.0f);
					blackboard.PublishMessage("motion", kse::messaging::Kind::Signal, std::move(walk));
				}

				/** Head yaw (left positive) and pitch (down positive), radians. */
				inline void Head(kse::messaging::Blackboard& blackboard, float yaw, float pitch) {
					auto head = std::make_shared<MotionHeadMessage>();
					head->set_command("setHead");
					head->add_parameter(yaw);
					head->add_parameter(pitch);
					blackboard.PublishMessage("motion", kse::messaging::Kind::Signal, std::move(head));
				}

				/** A motion of the robot's repertoire: "KickForwardLeft", "KickForwardRight", "Stand", ... */
				inline void Action(kse::messaging::Blackboard& blackboard, const std::string& command) {
					auto action = std::make_shared<MotionActionMessage>();
					action->set_command(command);
					blackboard.PublishMessage("motion", kse::messaging::Kind::Signal, std::move(action));
				}

				}  // namespace %2$s
				""".formatted(name, namespace(name));
	}

	static String chase(String name) {
		return """
				// Chase: walk at the ball, the head keeping it in sight; when the ball is not seen, turn on the
				// spot with the head sweeping until it is. %1$s.stct enters Chase again every 250 ms while
				// the game is in PLAYING, and each entry runs Execute() once: the walk it commands lasts
				// until the next run.
				#include "Chase.h"

				#include <cmath>

				#include <common/Robot.h>
				#include <statechart_engine/Factories.h>

				namespace {
				// registers the activity under the name the model's BASIC state has
				const statechart_engine::ActivityRegistrar<Chase> registrar("Chase");
				constexpr float kSweep[] = {0.0f, 0.8f, 1.5f, 0.8f, 0.0f, -0.8f, -1.5f, -0.8f};
				}  // namespace

				// once, before the first run: the topics to read
				void Chase::UserInit() { %2$s::Subscribe(*_blk); }

				// once per entry into the state Chase; the return value is not used
				int Chase::Execute() {
					const auto world = %2$s::World::Read(*_blk);
					if (!world.BallSeen()) {
						%2$s::Head(*_blk, kSweep[_step++ %% 8], 0.4f);
						%2$s::Walk(*_blk, 0.0f, 0.0f, 0.5f);
						return 0;
					}
					const float bearing = world.BallBearing();
					%2$s::Head(*_blk, bearing, 0.3f);
					// at a ball ahead, slowing down to stop with it in front of the feet; slowly while it is
					// to the side and the turn brings it ahead
					const float forward = std::fabs(bearing) < 0.5f ? 2.0f * (world.BallDistance() - 0.12f) : 0.2f;
					%2$s::Walk(*_blk, forward, 0.0f, 1.5f * bearing);
					return 0;
				}
				""".formatted(name, namespace(name));
	}

	static String waitActivity(String name) {
		return """
				// Wait: stand still and look ahead. %1$s.stct enters Wait while the game is not in PLAYING
				// (INITIAL, READY, SET, a penalty, FINISHED): the referee places the robot for the kick-off.
				#include "Wait.h"

				#include <common/Robot.h>
				#include <statechart_engine/Factories.h>

				namespace {
				const statechart_engine::ActivityRegistrar<Wait> registrar("Wait");
				}  // namespace

				void Wait::UserInit() { %2$s::Subscribe(*_blk); }

				int Wait::Execute() {
					%2$s::World::Read(*_blk);
					%2$s::Walk(*_blk, 0.0f, 0.0f, 0.0f);
					%2$s::Head(*_blk, 0.0f, 0.3f);
					return 0;
				}
				""".formatted(name, namespace(name));
	}

	/** The project's README: what is where, how to build and play, and how the model came from the formula. */
	static String readme(String name, Model model) {
		StringBuilder guards = new StringBuilder();
		for (Map.Entry<String[], String> guard : NewBehaviour.expressions(model).entrySet()) {
			guards.append("kse edit-transition ").append(name).append(".stct ").append(guard.getKey()[0]).append(' ').append(guard.getKey()[1])
					.append(" --expression '").append(guard.getValue()).append("'\n");
		}
		return """
				# %1$s

				A behaviour of your own for KSE, made by `kse new-behaviour %1$s`: Monas-style, it builds
				against the installed KSE runtime and plays on the simulated field against the example
				behaviours (Goalie, Attacker, Defender). The KSE docs' *Getting started in 10 minutes*
				(`docs/getting-started.md` in the KSE clone) takes it further.

				| file | what |
				|---|---|
				| `%1$s.liveness` | the liveness formula: `%2$s = play~`, `play = Wait \\| Chase` |
				| `%1$s.stct` | its statechart (`kse transform`, `kse label`) with the guards and timers below |
				| `src/activities/Wait/`, `src/activities/Chase/` | the activities: C++ classes run by the statechart |
				| `src/activities/common/Robot.h` | reading the world, commanding the legs and the head (docs/robot-messages.md) |
				| `CMakeLists.txt` | finds the runtime and the examples, builds `kse-match` with %1$s and the examples |

				## Build and play

				The KSE runtime and the examples must be installed in one folder, the *prefix*
				(`./kse demo` in the KSE clone installs both into `target/demo/runtime-prefix`), and the
				build needs the `kse` command (the clone's `./kse`) on the PATH or named with
				`-DKSE_EXECUTABLE=...`: it generates the statechart's C++ from `%1$s.stct` as it builds.

				```sh
				cmake -S . -B build -DCMAKE_PREFIX_PATH=<prefix>
				cmake --build build -j 2
				./build/kse-match --home Goalie:1,%1$s:2,%1$s:3 --away Goalie:1,Defender:2,Attacker:3 --log match.jsonl --svg match.svg
				```

				`kse-match` prints the score, the goals, stuck robots and behaviour failures; `match.jsonl`
				is the match's log (each robot's active states and the transitions it took, every 0.1 s),
				`match.svg` its picture. `./build/kse-match --list` lists the behaviours it can play.

				## How the model plays

				The formula says *what* runs (Wait or Chase, forever); the statechart's expressions say
				*when*. These four commands put them on the transformed formula, and they are what
				`%1$s.stct` holds:

				```sh
				%3$s```

				- `play` restarts only when its timer has passed (`[TimeoutCheck(behavior)]`) and sets it
				  again (`/TimeoutAction.behavior.250`): a loop without such a guard would run again at
				  once, forever, and never let the robot act (a livelock).
				- The CONDITION state chooses by the game state: Chase in PLAYING, Wait otherwise.
				- An activity's `Execute()` runs once per entry into its state; what it commands (a walk)
				  lasts until the next command.

				After changing the formula, `kse transform %1$s.liveness` and `kse label %1$s.stct` make the
				statechart again *without* expressions: set them again with `kse edit-transition` (the
				labels may change: `kse diagram %1$s.stct` draws them). A new activity's skeleton comes from
				`kse generate %1$s.stct src --no-statechart` (existing activities are never overwritten).
				Activity names are global in one program: an activity named like one of the examples'
				(Init, Scan, Stare, Kick, GoToPosition, ApproachBall, Guard, NoPlay, SpecialAction) stops
				the CMake configuration with both named.
				""".formatted(name, NewBehaviour.rootName(name), guards);
	}
}
