package org.kse.generator.monas.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.generator.monas.MonasGenerator;
import org.kse.generator.monas.MonasGenerator.Options;
import org.kse.generator.monas.MonasGenerator.Report;
import org.kse.model.StatechartResources;

/**
 * Generating into a Monas-style tree (tests/data/monas-tree) whose messages/ replaces a built-in
 * message and adds its own: the checks use the tree's definitions, and the generated CMake never
 * compiles a second C++ type of a name kse::messages already holds.
 */
class MonasTreeTest {

	private static final Path TREE = Path.of(System.getProperty("kse.repository", "../.."), "tests", "data", "monas-tree");

	/** A copy of the tree, since generating writes into its source folder. */
	private static Path copy(Path into) throws IOException {
		try (Stream<Path> walk = Files.walk(TREE)) {
			for (Path file : walk.filter(Files::isRegularFile).toList()) {
				Path target = into.resolve(TREE.relativize(file).toString());
				Files.createDirectories(target.getParent());
				Files.copy(file, target);
			}
		}
		return into;
	}

	@Test
	void theTreesMessagesAreUsedAndTheReplacedBuiltInIsReported(@TempDir Path folder) throws Exception {
		Path tree = copy(folder);
		Path source = tree.resolve("src");
		Report report = MonasGenerator.generate(StatechartResources.load(tree.resolve("models/Localizer.stct")), source, Options.DEFAULT);
		assertEquals(1, report.replacements().size(), report.replacements()::toString);
		assertEquals("GameStateMessage", report.replacements().get(0).type());
		assertEquals(source.resolve("messages/Gamecontroller.proto").toAbsolutePath().normalize(), report.replacements().get(0).file());
		assertTrue(report.kept().contains(Path.of("activities", "Localize")), report.kept()::toString);
		assertEquals(List.of("0.3->0.4 (Approach_TO_0.4): expression 1:36: the generated C++ will not compile: 'GameStateMessage' has no field"
				+ " 'penalty_secs_left' in the KSE runtime's messages, which it is built with"), report.warnings(),
				"a field only the tree's GameStateMessage has is named before anyone builds");

		Path transitions = source.resolve("statecharts/Localizer/transitions");
		String approach = Files.readString(transitions.resolve("TrCond_0_2_TO_0_3.h"));
		assertTrue(approach.contains("#include \"Localization.pb.h\""), approach);
		assertFalse(approach.contains("Gamecontroller.pb.h"), "the replaced built-in is the runtime's in C++: " + approach);
		assertTrue(approach.contains("const auto msg0 = msg0_.ReadState();") && approach.contains("kse::messaging::Reader<LocalizeDone> msg0_;"), approach);
		assertTrue(approach.contains("(msg0 != nullptr && msg0->moveon() == 1) && (msg1 != nullptr && msg1->player_state() == PLAYER_PLAYING)"), approach);
		String loop = Files.readString(transitions.resolve("TrCond_0_2_TO_0_2.h"));
		assertTrue(loop.contains("(statechart_engine::TimeoutCheck(*_blk, timeout0) && (msg0 != nullptr && !msg0->moveon()))"), loop);

		String cmake = Files.readString(source.resolve("statecharts/Localizer/CMakeLists.txt"));
		assertTrue(cmake.contains("kse_add_messages(kse_user_messages\n\t\tPROTOS\n\t\t\t${CMAKE_CURRENT_SOURCE_DIR}/../../messages/Localization.proto\n\t\tIMPORT_DIRS"),
				cmake);
		assertFalse(cmake.contains("${CMAKE_CURRENT_SOURCE_DIR}/../../messages/Gamecontroller.proto"), "not compiled next to kse::messages: " + cmake);
		assertTrue(cmake.contains("# messages/Gamecontroller.proto is not compiled: it defines GameStateMessage again, which kse::messages"), cmake);
		assertFalse(cmake.contains("FATAL_ERROR"), cmake);
		assertTrue(cmake.contains("target_link_libraries(statechart_Localizer PUBLIC kse_user_messages)"), cmake);
	}

	@Test
	void aFileReplacingABuiltInNextToTypesOfItsOwnStopsTheBuildWithWhatToDo(@TempDir Path folder) throws Exception {
		Path tree = copy(folder);
		Path source = tree.resolve("src");
		Files.writeString(source.resolve("messages/Team.proto"),
				"syntax = \"proto2\";\nmessage FallMessage { optional int32 fall = 1; optional int32 side = 2; }\nmessage TeamPlan { optional int32 formation = 1; }\n");
		MonasGenerator.generate(StatechartResources.load(tree.resolve("models/Localizer.stct")), source, Options.DEFAULT);
		String cmake = Files.readString(source.resolve("statecharts/Localizer/CMakeLists.txt"));
		assertTrue(cmake.contains("message(FATAL_ERROR \"messages/Team.proto defines FallMessage, which the KSE runtime's messages define already, next to"
				+ " TeamPlan: move that type into a .proto file of its own and generate again\")"), cmake);
		assertFalse(cmake.contains("../../messages/Team.proto"), cmake);
		assertTrue(cmake.contains("../../messages/Localization.proto"), cmake);
	}

	@Test
	void aTreeWhoseMessagesAllReplaceBuiltInsBuildsNoMessageLibrary(@TempDir Path folder) throws Exception {
		Path tree = copy(folder);
		Path source = tree.resolve("src");
		Files.delete(source.resolve("messages/Localization.proto"));
		Path model = tree.resolve("models/Localizer.stct");
		Files.writeString(model, Files.readString(model).replace("behavior.State.LocalizeDone.moveon()", "behavior.State.HeadToBMessage.ballfound()"));
		MonasGenerator.generate(StatechartResources.load(model), source, Options.DEFAULT);
		String cmake = Files.readString(source.resolve("statecharts/Localizer/CMakeLists.txt"));
		assertFalse(cmake.contains("kse_user_messages"), cmake);
		assertTrue(cmake.contains("# messages/Gamecontroller.proto is not compiled"), cmake);
		List<String> headers = Files.readAllLines(source.resolve("statecharts/Localizer/transitions/TrCond_0_3_TO_0_4.h")).stream()
				.filter(line -> line.startsWith("#include")).toList();
		assertEquals(List.of("#include <kse/behavior/BehaviorConst.h>", "#include <kse/behavior/Guards.h>", "#include <kse/messages/all.h>",
				"#include <statechart_engine/Interfaces.h>"), headers);
	}
}
