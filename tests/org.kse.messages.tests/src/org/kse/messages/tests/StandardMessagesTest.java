package org.kse.messages.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kse.messages.tests.Protos.assertNoProblems;
import static org.kse.messages.tests.Protos.write;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.SequencedMap;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.messages.Field;
import org.kse.messages.FieldType;
import org.kse.messages.MessageCatalog;
import org.kse.messages.MessageType;
import org.kse.messages.ProtoFile;
import org.kse.messages.ProtoReader;
import org.kse.messages.StandardMessages;

/** The standard messages merged with a source tree's own: the tree's definition of a name wins. */
class StandardMessagesTest {

	@TempDir
	Path dir;

	private static final String GAME_STATE = """
			syntax = "proto2";
			message GameStateMessage {
			  optional int32 player_state = 5;
			  optional int32 penalty_secs_left = 15;
			}
			""";

	@Test
	void aTreesMessageReplacesTheBuiltInOfTheSameName() {
		write(dir, "Gamecontroller.proto", GAME_STATE);
		write(dir, "Localization.proto", "syntax = \"proto2\";\nmessage LocalizeDone { optional int32 moveon = 1; }\n");
		StandardMessages.Merged merged = StandardMessages.merge(List.of(dir));
		MessageCatalog catalog = merged.catalog();
		MessageType game = catalog.message("GameStateMessage").orElseThrow();
		assertEquals(List.of("player_state", "penalty_secs_left"), game.fields().stream().map(Field::name).toList());
		assertEquals(Path.of("Gamecontroller.proto"), game.file(), "the tree's file, a file of its own beside the standard one");
		assertTrue(catalog.message("LocalizeDone").isPresent());
		assertTrue(catalog.message("HeadToBMessage").isPresent(), "the other built-ins stay");
		assertNoProblems(catalog.problems());
		assertEquals(List.of(new StandardMessages.Replacement("GameStateMessage", Path.of("kse/messages/Gamecontroller.proto"),
				dir.resolve("Gamecontroller.proto"))), merged.replacements());

		MessageType standard = StandardMessages.catalog().message("GameStateMessage").orElseThrow();
		assertTrue(standard.field("penalty_secs_left").isEmpty(), "the standard catalog is not changed by a merge");
		assertTrue(StandardMessages.isStandard(standard.file()));
		assertFalse(StandardMessages.isStandard(game.file()));
	}

	@Test
	void aReplacedBuiltInThatOtherBuiltInsUseLeavesTheSharedStandardFilesAlone() {
		write(dir, "Ball.proto", "syntax = \"proto2\";\nmessage Ball { optional float distance = 1; }\n");
		MessageCatalog merged = StandardMessages.merge(List.of(dir)).catalog();
		MessageType ball = merged.message("Ball").orElseThrow();
		assertEquals(List.of("distance"), ball.fields().stream().map(Field::name).toList());
		MessageType standardWorld = StandardMessages.catalog().message("WorldInfo").orElseThrow();
		FieldType balls = standardWorld.field("balls").orElseThrow().type();
		assertTrue(balls instanceof FieldType.Message message && StandardMessages.isStandard(message.type().file()),
				"the standard WorldInfo still holds the standard Ball: " + balls);
	}

	@Test
	void aTreeWithoutReplacementsReplacesNothingAndCanImportTheStandardFiles() {
		write(dir, "Team.proto", """
				syntax = "proto2";
				import "kse/messages/WorldInfo.proto";
				message TeamMessage { optional WorldInfo seen = 1; }
				""");
		StandardMessages.Merged merged = StandardMessages.merge(List.of(dir));
		assertEquals(List.of(), merged.replacements());
		assertNoProblems(merged.catalog().problems());
		MessageType team = merged.catalog().message("TeamMessage").orElseThrow();
		assertTrue(merged.catalog().resolveMember(team, List.of("seen", "balls")).isPresent());
		assertEquals(List.of(), StandardMessages.merge(List.of(dir.resolve("missing"))).replacements());
	}

	@Test
	void parsedFilesMergeAsTheirFolderWouldWithAnEditorsTextInPlaceOfTheDisk() {
		write(dir, "Common.proto", "syntax = \"proto2\";\nmessage Position { optional float x = 1; }\n");
		write(dir, "Team.proto", "syntax = \"proto2\";\nimport \"Common.proto\";\nmessage Team { optional Position where = 1; }\n");
		// the editor's unsaved text of Team.proto names a type nobody declares
		SequencedMap<Path, ProtoFile> files = new LinkedHashMap<>();
		files.put(dir.resolve("Common.proto"), ProtoReader.read(Path.of("Common.proto"), "syntax = \"proto2\";\nmessage Position { optional float x = 1; }\n"));
		files.put(dir.resolve("Team.proto"), ProtoReader.read(Path.of("Team.proto"),
				"syntax = \"proto2\";\nimport \"Common.proto\";\nmessage Team { optional Positon where = 1; }\nmessage GameStateMessage { optional int32 x = 1; }\n"));
		StandardMessages.Merged merged = StandardMessages.merge(files);
		assertEquals(List.of(dir.resolve("Team.proto") + ":3:25: unknown type Positon of field where in message Team"),
				merged.problems().stream().map(Object::toString).toList(), "the problems with the paths a user opens");
		assertEquals(List.of(new StandardMessages.Replacement("GameStateMessage", Path.of("kse/messages/Gamecontroller.proto"),
				dir.resolve("Team.proto"))), merged.replacements());
		assertNoProblems(StandardMessages.merge(List.of(dir)).problems());
	}
}
