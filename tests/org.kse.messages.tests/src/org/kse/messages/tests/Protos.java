package org.kse.messages.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;

import org.kse.messages.ProtoFile;
import org.kse.messages.ProtoReader;
import org.kse.messages.ProtoProblem;

/** Realistic Monas-style sample files and small helpers shared by the tests. */
final class Protos {

	private Protos() {
	}

	static final String COMMON = """
			// Shared by every Monas message.
			syntax = "proto2";

			message Header {
			  optional uint64 timestamp = 1;
			  optional string host = 2 [default = "nao;}"];
			}
			""";

	static final String WORLD_INFO = """
			// Monas world model, as the localisation publishes it on topic worldstate.
			syntax = "proto2";

			import "common.proto";

			message WorldInfo {
			  message Position {
			    required float X = 1;
			    required float Y = 2;
			    required float phi = 3;
			    optional float confidence = 4 [default = 0];
			  }
			  message Ball {
			    required float relativeX = 1;
			    required float relativeY = 2;
			    optional float relativeXspeed = 3;
			    optional float relativeYspeed = 4;
			    optional Position absolute = 5;
			  }
			  required Position myPosition = 1;
			  repeated Ball balls = 2;
			  optional Header header = 3;
			}
			""";

	static final String GAME_STATE = """
			syntax = "proto2";
			/* Published by the game controller listener on topic worldstate.
			   Numbers follow the RoboCup SPL game controller. */
			enum PlayerState {
			  PLAYER_INITIAL = 0;
			  PLAYER_READY = 1;
			  PLAYER_SET = 2;
			  PLAYER_PLAYING = 3;
			  PLAYER_FINISHED = 4;
			  PLAYER_PENALISED = 5;
			}

			message GameStateMessage {
			  optional int32 player_number = 1;
			  optional int32 team_number = 2;
			  optional int32 team_color = 3;
			  optional int32 own_goal_color = 4;
			  optional PlayerState player_state = 5 [default = PLAYER_INITIAL];
			  optional int32 game_state = 6;
			  optional int32 sec_game_state = 7;
			  optional bool firstHalf = 8;
			  optional int32 penalty = 9;
			  optional bool kickoff = 10;
			  optional int32 our_score = 11;
			  optional int32 otherteam_score = 12;
			}

			message HeadToBMessage {
			  required int32 ballfound = 1;
			  optional int32 calibrated = 2;
			}
			""";

	/** proto3 with a package, options, map, oneof, reserved, a service and forward references. */
	static final String MOTION = """
			syntax = "proto3";
			package kse.motion;
			option java_package = "org.kse.motion";
			option optimize_for = SPEED;

			message MotionWalkMessage {
			  string command = 1;
			  repeated float parameter = 2 [packed = true];
			  map<string, float> tuning = 3;
			  oneof target {
			    Pose2D pose = 4;
			    .kse.motion.Velocity velocity = 5;
			  }
			  reserved 6, 8 to 10;
			  reserved "old_field";
			  message Pose2D { float x = 1; float y = 2; float theta = 3; }
			  enum Mode { MODE_UNSPECIFIED = 0; MODE_WALK = 1 [deprecated = true]; MODE_STOP = 2; }
			  Mode mode = 11;
			}

			message Velocity { float vx = 1; float vy = 2; float vtheta = 3; }

			service MotionService {
			  rpc Walk (MotionWalkMessage) returns (Velocity) { option deadline = 1.0; }
			  rpc Stop (Velocity) returns (Velocity);
			}
			""";

	static ProtoFile parse(String text) {
		return ProtoReader.read(Path.of("test.proto"), text);
	}

	/** "line:column" (1-based) of the first occurrence of {@code needle} in {@code text}. */
	static String pos(String text, String needle) {
		int index = text.indexOf(needle);
		if (index < 0) {
			fail("'" + needle + "' not in the sample");
		}
		String before = text.substring(0, index);
		int line = (int) before.chars().filter(c -> c == '\n').count() + 1;
		int column = index - before.lastIndexOf('\n');
		return line + ":" + column;
	}

	static String at(ProtoProblem problem) {
		return problem.line() + ":" + problem.column();
	}

	static void assertNoProblems(List<ProtoProblem> problems) {
		assertTrue(problems.isEmpty(), () -> "unexpected problems:\n"
				+ problems.stream().map(ProtoProblem::toString).collect(Collectors.joining("\n")));
	}

	/** The one problem whose message contains {@code fragment}. */
	static ProtoProblem problem(List<ProtoProblem> problems, String fragment) {
		List<ProtoProblem> matching = problems.stream().filter(p -> p.message().contains(fragment)).toList();
		assertEquals(1, matching.size(), () -> "problems containing '" + fragment + "' in " + problems);
		return matching.get(0);
	}

	static Path write(Path dir, String relative, String text) {
		try {
			Path file = dir.resolve(relative);
			Files.createDirectories(file.getParent());
			return Files.writeString(file, text);
		} catch (IOException e) {
			throw new UncheckedIOException(e);
		}
	}
}
