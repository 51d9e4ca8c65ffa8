package org.kse.messages.tests;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kse.messages.tests.Protos.assertNoProblems;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.kse.messages.MessageCatalog;
import org.kse.messages.MessageType;

/** The standard message set shipped with the C++ runtime must load cleanly. */
class RuntimeMessagesTest {

	@Test
	void runtimeMessagesLoadWithoutProblems() throws IOException {
		Optional<Path> folder = runtimeMessages();
		Assumptions.assumeTrue(folder.isPresent(), "runtime/messages not found");
		try (Stream<Path> files = Files.list(folder.get())) {
			Assumptions.assumeTrue(files.anyMatch(p -> p.toString().endsWith(".proto")), "no .proto files yet");
		}
		MessageCatalog catalog = MessageCatalog.load(List.of(folder.get()));
		assertNoProblems(catalog.problems());
		// The messages of reference section 9, by the simple names generated code uses.
		for (String name : List.of("GameStateMessage", "HeadToBMessage", "BToHeadMessage", "PositionMessage",
				"ReturnToPositionMessage", "FallMessage", "TimeoutMsg", "WorldInfo", "MotionWalkMessage",
				"MotionHeadMessage", "MotionActionMessage")) {
			assertTrue(catalog.message(name).isPresent(), name);
		}
		MessageType worldInfo = catalog.message("WorldInfo").orElseThrow();
		assertTrue(catalog.resolveMember(worldInfo, List.of("myPosition", "X")).isPresent());
		assertTrue(catalog.resolveMember(worldInfo, List.of("balls")).orElseThrow().isRepeated());
		assertTrue(catalog.resolveMember(catalog.message("GameStateMessage").orElseThrow(), List.of("player_state"))
				.isPresent());
		assertNoProblems(catalog.problems()); // the look-ups above found nothing ambiguous
	}

	/** In the repository the build names, next to its examples folder, or above the working directory. */
	private static Optional<Path> runtimeMessages() {
		String repository = System.getProperty("kse.repository");
		if (repository != null && Files.isDirectory(Path.of(repository, "runtime/messages"))) {
			return Optional.of(Path.of(repository, "runtime/messages"));
		}
		String examples = System.getProperty("kse.examples");
		if (examples != null) {
			Path parent = Path.of(examples).toAbsolutePath().getParent();
			if (parent != null && Files.isDirectory(parent.resolve("runtime/messages"))) {
				return Optional.of(parent.resolve("runtime/messages"));
			}
		}
		for (Path dir = Path.of("").toAbsolutePath(); dir != null; dir = dir.getParent()) {
			if (Files.isDirectory(dir.resolve("runtime/messages"))) {
				return Optional.of(dir.resolve("runtime/messages"));
			}
		}
		return Optional.empty();
	}
}
