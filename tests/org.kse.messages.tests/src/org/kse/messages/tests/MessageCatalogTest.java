package org.kse.messages.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kse.messages.tests.Protos.assertNoProblems;
import static org.kse.messages.tests.Protos.at;
import static org.kse.messages.tests.Protos.pos;
import static org.kse.messages.tests.Protos.problem;
import static org.kse.messages.tests.Protos.write;

import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.messages.EnumType;
import org.kse.messages.Field;
import org.kse.messages.FieldType;
import org.kse.messages.MessageCatalog;
import org.kse.messages.MessageType;
import org.kse.messages.ProtoReader;
import org.kse.messages.ProtoProblem;
import org.kse.messages.ScalarKind;

/** Loading folders, linking files and types, and the queries of the validator and generator. */
class MessageCatalogTest {

	@TempDir
	Path dir;

	private MessageCatalog monas() {
		write(dir, "common.proto", Protos.COMMON);
		write(dir, "WorldInfo.proto", Protos.WORLD_INFO);
		write(dir, "gamecontroller/GameState.proto", Protos.GAME_STATE);
		write(dir, "motion/Motion.proto", Protos.MOTION);
		write(dir, "README.txt", "not a proto file");
		return MessageCatalog.load(List.of(dir));
	}

	@Test
	void loadsEveryProtoFileRecursivelyInPathOrder() {
		MessageCatalog catalog = monas();
		assertNoProblems(catalog.problems());
		assertEquals(List.of("WorldInfo.proto", "common.proto", "GameState.proto", "Motion.proto"),
				catalog.files().stream().map(f -> f.file().getFileName().toString()).toList());
		assertEquals(List.of("WorldInfo", "WorldInfo.Position", "WorldInfo.Ball", "Header", "GameStateMessage",
				"HeadToBMessage", "kse.motion.MotionWalkMessage", "kse.motion.MotionWalkMessage.Pose2D",
				"kse.motion.Velocity"), catalog.messages().stream().map(MessageType::fullName).toList());
	}

	@Test
	void resolvesScalarsSameFileNestedAndImportedTypes() {
		MessageCatalog catalog = monas();
		MessageType worldInfo = catalog.message("WorldInfo").orElseThrow();
		MessageType position = catalog.message("WorldInfo.Position").orElseThrow();
		MessageType ball = catalog.message("WorldInfo.Ball").orElseThrow();
		assertEquals(new FieldType.Message(position), worldInfo.field("myPosition").orElseThrow().type());
		assertEquals(new FieldType.Message(ball), worldInfo.field("balls").orElseThrow().type());
		assertEquals(new FieldType.Message(position), ball.field("absolute").orElseThrow().type(),
				"a sibling nested type, found in the enclosing scope");
		assertSame(catalog.message("Header").orElseThrow(),
				worldInfo.field("header").orElseThrow().messageType().orElseThrow(), "from the imported common.proto");
		assertEquals(new FieldType.Scalar(ScalarKind.FLOAT), position.field("X").orElseThrow().type());

		EnumType playerState = catalog.enumType("PlayerState").orElseThrow();
		Field state = catalog.message("GameStateMessage").orElseThrow().field("player_state").orElseThrow();
		assertEquals(playerState, state.enumType().orElseThrow());
		assertTrue(state.isResolved());
	}

	@Test
	void resolvesPackageQualifiedAndForwardReferences() {
		MessageCatalog catalog = monas();
		MessageType walk = catalog.message("kse.motion.MotionWalkMessage").orElseThrow();
		assertSame(walk, catalog.message("MotionWalkMessage").orElseThrow(), "simple name");
		assertSame(walk, catalog.message(".kse.motion.MotionWalkMessage").orElseThrow(), "leading dot");
		assertEquals("kse.motion.MotionWalkMessage.Pose2D",
				walk.field("pose").orElseThrow().messageType().orElseThrow().fullName(), "declared after its use");
		assertEquals("kse.motion.Velocity", walk.field("velocity").orElseThrow().messageType().orElseThrow().fullName());
		assertEquals("kse.motion.MotionWalkMessage.Mode", walk.field("mode").orElseThrow().enumType().orElseThrow()
				.fullName());
		assertEquals(ScalarKind.FLOAT, walk.field("tuning").orElseThrow().scalarKind().orElseThrow());
	}

	@Test
	void innermostScopeWinsAndPartlyQualifiedNamesResolve() {
		write(dir, "scopes.proto", """
				syntax = "proto3";
				package robot;
				message Pose { float x = 1; }
				message Team {
				  message Pose { float y = 1; }
				  Pose own = 1;
				  .robot.Pose global = 2;
				  robot.Pose alsoGlobal = 3;
				  message Player { Pose inherited = 1; Team.Pose explicit = 2; }
				}
				""");
		MessageCatalog catalog = MessageCatalog.load(List.of(dir));
		assertNoProblems(catalog.problems());
		MessageType team = catalog.message("Team").orElseThrow();
		MessageType nestedPose = catalog.message("robot.Team.Pose").orElseThrow();
		MessageType topPose = catalog.message("Pose").orElseThrow();
		assertEquals("robot.Pose", topPose.fullName(), "top-level wins over nested for a simple name");
		assertSame(nestedPose, team.field("own").orElseThrow().messageType().orElseThrow());
		assertSame(topPose, team.field("global").orElseThrow().messageType().orElseThrow());
		assertSame(topPose, team.field("alsoGlobal").orElseThrow().messageType().orElseThrow());
		MessageType player = catalog.message("Team.Player").orElseThrow();
		assertSame(nestedPose, player.field("inherited").orElseThrow().messageType().orElseThrow());
		assertSame(nestedPose, player.field("explicit").orElseThrow().messageType().orElseThrow());
	}

	@Test
	void importsByRelativePathAndImportPublic() {
		write(dir, "base/geometry.proto", """
				syntax = "proto2";
				package geo;
				message Point { optional float x = 1; optional float y = 2; }
				""");
		write(dir, "base/reexport.proto", """
				syntax = "proto2";
				import public "base/geometry.proto";
				""");
		write(dir, "vision/ball.proto", """
				syntax = "proto2";
				import "base/reexport.proto";
				message BallObject { optional geo.Point center = 1; }
				""");
		write(dir, "vision/goal.proto", """
				syntax = "proto2";
				import "../base/geometry.proto";
				message GoalPost { optional geo.Point base = 1; }
				""");
		MessageCatalog catalog = MessageCatalog.load(List.of(dir));
		assertNoProblems(catalog.problems());
		MessageType point = catalog.message("geo.Point").orElseThrow();
		assertSame(point, catalog.message("BallObject").orElseThrow().field("center").orElseThrow().messageType()
				.orElseThrow(), "through import public");
		assertSame(point, catalog.message("GoalPost").orElseThrow().field("base").orElseThrow().messageType()
				.orElseThrow(), "relative to the importing file");
	}

	@Test
	void typesFromFilesThatAreNotImportedAreReportedButResolved() {
		write(dir, "a.proto", "message A { optional int32 a = 1; }\n");
		String b = "import \"missing.proto\";\nmessage B {\n  optional A a = 1;\n}\n";
		write(dir, "b.proto", b);
		MessageCatalog catalog = MessageCatalog.load(List.of(dir));
		ProtoProblem notImported = problem(catalog.problems(), "does not import");
		assertEquals(dir.resolve("b.proto"), notImported.file());
		assertEquals(pos(b, "A a"), at(notImported));
		assertEquals("type A is defined in a.proto, which b.proto does not import", notImported.message());
		assertEquals(pos(b, "\"missing.proto\""), at(problem(catalog.problems(), "\"missing.proto\" not found")));
		assertTrue(catalog.message("B").orElseThrow().field("a").orElseThrow().messageType().isPresent());
	}

	@Test
	void unresolvedTypeIsReportedAtItsExactPosition() {
		String text = """
				syntax = "proto2";

				message BToHeadMessage {
				  required int32 headaction = 1;
				  optional   HeadMode  mode = 2;
				  repeated Nested.Missing deep = 3;
				}
				""";
		write(dir, "head.proto", text);
		MessageCatalog catalog = MessageCatalog.load(List.of(dir));
		assertEquals(2, catalog.problems().size(), () -> catalog.problems().toString());
		ProtoProblem mode = catalog.problems().get(0);
		assertEquals(dir.resolve("head.proto"), mode.file());
		assertEquals(5, mode.line());
		assertEquals(14, mode.column());
		assertEquals("unknown type HeadMode of field mode in message BToHeadMessage", mode.message());
		assertEquals(pos(text, "Nested.Missing"), at(catalog.problems().get(1)));
		Field field = catalog.message("BToHeadMessage").orElseThrow().field("mode").orElseThrow();
		assertEquals(new FieldType.Unresolved("HeadMode"), field.type());
		assertFalse(field.isResolved());
	}

	@Test
	void duplicateAndAmbiguousNames() {
		write(dir, "one.proto", "package a;\nmessage Fall { optional int32 fall = 1; }\nmessage Dup {}\n");
		String two = "package b;\nmessage Fall { optional int32 side = 1; }\n";
		write(dir, "two.proto", two);
		String three = "package a;\nmessage Dup {}\n";
		write(dir, "three.proto", three);
		MessageCatalog catalog = MessageCatalog.load(List.of(dir));
		ProtoProblem duplicate = problem(catalog.problems(), "duplicate type name a.Dup");
		assertEquals(dir.resolve("three.proto"), duplicate.file());
		assertEquals(pos(three, "Dup"), at(duplicate));
		assertTrue(duplicate.message().contains("one.proto:3:9"), duplicate::message);
		assertEquals(1, catalog.problems().size(), "nothing ambiguous asked yet");

		assertEquals("a.Fall", catalog.message("Fall").orElseThrow().fullName(), "the first in catalog order");
		assertEquals("a.Fall", catalog.message("Fall").orElseThrow().fullName());
		ProtoProblem ambiguous = problem(catalog.problems(), "ambiguous");
		assertEquals(dir.resolve("two.proto"), ambiguous.file());
		assertEquals(pos(two, "Fall"), at(ambiguous));
		assertEquals(2, catalog.problems().size(), "reported once");
		assertEquals("b.Fall", catalog.message("b.Fall").orElseThrow().fullName(), "full names stay exact");
		assertTrue(catalog.message("Nothing").isEmpty());
		assertTrue(catalog.enumType("Fall").isEmpty(), "a message is not an enum");
	}

	@Test
	void enumValuesForGuards() {
		MessageCatalog catalog = monas();
		assertTrue(catalog.hasEnumValue("PLAYER_PLAYING"));
		assertTrue(catalog.hasEnumValue("PLAYER_PENALISED"));
		assertTrue(catalog.hasEnumValue("MODE_WALK"), "nested enums count too");
		assertTrue(catalog.hasEnumValue("PlayerState.PLAYER_SET"));
		assertFalse(catalog.hasEnumValue("PLAYER_DANCING"));
		assertFalse(catalog.hasEnumValue("Mode.PLAYER_SET"));
		assertFalse(catalog.hasEnumValue("player_state"), "a field is not an enum value");
		assertEquals(3, catalog.enumType("PlayerState").orElseThrow().value("PLAYER_PLAYING").getAsInt());
	}

	@Test
	void resolveMemberWalksNestedMessageFields() {
		MessageCatalog catalog = monas();
		MessageType worldInfo = catalog.message("WorldInfo").orElseThrow();
		Field x = catalog.resolveMember(worldInfo, List.of("myPosition", "X")).orElseThrow();
		assertEquals("X", x.name());
		assertEquals("WorldInfo.Position", x.containingType().fullName());
		assertEquals(ScalarKind.FLOAT, x.scalarKind().orElseThrow());

		assertEquals("myPosition", catalog.resolveMember(worldInfo, List.of("myPosition")).orElseThrow().name());
		assertEquals("balls", catalog.resolveMember(worldInfo, List.of("balls")).orElseThrow().name());
		assertEquals("timestamp", catalog.resolveMember(worldInfo, List.of("header", "timestamp")).orElseThrow()
				.name(), "across files");

		assertTrue(catalog.resolveMember(worldInfo, List.of("myPosition", "z")).isEmpty(), "no such field");
		assertTrue(catalog.resolveMember(worldInfo, List.of("Position")).isEmpty(), "a nested type is not a field");
		assertTrue(catalog.resolveMember(worldInfo, List.of("myPosition", "X", "more")).isEmpty(), "past a scalar");
		assertTrue(catalog.resolveMember(worldInfo, List.of("balls", "relativeX")).isEmpty(),
				"a repeated field needs an index first");
		assertTrue(catalog.resolveMember(worldInfo, List.of()).isEmpty());

		MessageType game = catalog.message("GameStateMessage").orElseThrow();
		assertEquals("player_state", catalog.resolveMember(game, List.of("player_state")).orElseThrow().name());
		assertTrue(catalog.resolveMember(game, List.of("player_state", "PLAYER_PLAYING")).isEmpty());
	}

	@Test
	void standardTopicsAreTheMonasOnes() {
		assertEquals(List.of("behavior", "worldstate", "vision", "motion", "sensors", "communication", "obstacle",
				"external", "buttonevents"), MessageCatalog.standardTopics());
	}

	@Test
	void missingFoldersAndSingleFilesAsRoots() {
		Path file = write(dir, "single/Fall.proto", "message FallMessage { optional int32 fall = 1; }\n");
		Path missing = dir.resolve("nowhere");
		MessageCatalog catalog = MessageCatalog.load(List.of(missing, file, dir.resolve("single")));
		assertEquals(1, catalog.files().size(), "the same file through two roots is read once");
		assertTrue(catalog.message("FallMessage").isPresent());
		ProtoProblem notFound = problem(catalog.problems(), "not found");
		assertEquals(missing, notFound.file());
		assertEquals("1:1", at(notFound));
		assertTrue(MessageCatalog.load(List.of()).messages().isEmpty());
	}

	@Test
	void catalogOfParsedBuffers() {
		MessageCatalog catalog = MessageCatalog.of(List.of(ProtoReader.read(Path.of("common.proto"), Protos.COMMON),
				ProtoReader.read(Path.of("WorldInfo.proto"), Protos.WORLD_INFO)));
		assertNoProblems(catalog.problems());
		assertTrue(catalog.message("WorldInfo").orElseThrow().field("header").orElseThrow().messageType().isPresent());
	}

	@Test
	void loadingIsDeterministic(@TempDir Path other) {
		// Same files written in the opposite order into a second folder: file systems list them differently.
		List<String> names = List.of("z.proto", "a/m.proto", "a/b.proto", "k.proto");
		for (int i = 0; i < names.size(); i++) {
			String text = "message M" + i + " { optional Unknown" + i + " u = 1; optional M" + ((i + 1) % 4)
					+ " next = 2; }\nmessage Same { }\n";
			write(dir, names.get(i), text);
			write(other, names.get(i), text);
		}
		MessageCatalog first = MessageCatalog.load(List.of(dir));
		MessageCatalog second = MessageCatalog.load(List.of(dir));
		assertEquals(describe(first, dir), describe(second, dir));
		assertEquals(describe(first, dir), describe(MessageCatalog.load(List.of(other)), other));
		assertEquals(List.of("M2", "Same", "M1", "M3", "M0"),
				first.messages().stream().map(MessageType::fullName).toList(), "a/b, a/m, k, z");
	}

	private static String describe(MessageCatalog catalog, Path root) {
		StringBuilder s = new StringBuilder();
		catalog.messages().forEach(m -> s.append(m.fullName()).append(m.fields()).append('\n'));
		catalog.problems().forEach(p -> s.append(root.relativize(p.file())).append(':').append(at(p)).append(' ')
				.append(p.message()).append('\n'));
		return s.toString();
	}
}
