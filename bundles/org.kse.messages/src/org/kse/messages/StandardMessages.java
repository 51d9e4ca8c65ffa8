package org.kse.messages;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/**
 * The message set every KSE behaviour can use: the runtime's {@code runtime/messages/*.proto},
 * copied into this bundle by the build, plus whatever a user's source tree adds.
 */
public final class StandardMessages {

	/** The runtime's .proto files, as bundled under {@code org/kse/messages/standard/}. */
	public static final List<String> FILES = List.of("Behavior.proto", "Gamecontroller.proto", "Motion.proto", "WorldInfo.proto");

	private static volatile List<ProtoFile> standard;

	private StandardMessages() {
	}

	/** The standard files, parsed once. */
	public static List<ProtoFile> files() {
		List<ProtoFile> result = standard;
		if (result == null) {
			List<ProtoFile> parsed = new ArrayList<>();
			for (String name : FILES) {
				try (InputStream in = StandardMessages.class.getResourceAsStream("standard/" + name)) {
					if (in == null) {
						throw new IllegalStateException("the KSE bundle lacks its standard message file " + name);
					}
					parsed.add(ProtoParser.parse(Path.of(name), new String(in.readAllBytes(), StandardCharsets.UTF_8)));
				} catch (IOException e) {
					throw new UncheckedIOException(e);
				}
			}
			standard = result = List.copyOf(parsed);
		}
		return result;
	}

	/** The standard messages alone. */
	public static MessageCatalog catalog() {
		return MessageCatalog.of(files());
	}

	/**
	 * The standard messages and every {@code *.proto} under the given folders (a user's
	 * {@code messages/} folder, say). Files are named relative to their folder, so imports
	 * between them resolve as protoc would with that folder on its path.
	 */
	public static MessageCatalog catalog(List<Path> folders) {
		List<ProtoFile> files = new ArrayList<>(files());
		for (Path folder : folders) {
			if (!Files.isDirectory(folder)) {
				continue;
			}
			try (Stream<Path> walk = Files.walk(folder)) {
				for (Path file : walk.filter(p -> p.toString().endsWith(".proto") && Files.isRegularFile(p)).sorted().toList()) {
					files.add(ProtoParser.parse(folder.relativize(file), Files.readString(file, StandardCharsets.UTF_8)));
				}
			} catch (IOException e) {
				throw new UncheckedIOException(e);
			}
		}
		return MessageCatalog.of(files);
	}
}
