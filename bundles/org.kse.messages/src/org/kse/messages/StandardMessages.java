package org.kse.messages;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.MalformedInputException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.SequencedMap;
import java.util.Set;
import java.util.stream.Stream;

/**
 * The message set every KSE behaviour can use: the runtime's {@code runtime/messages/*.proto},
 * copied into this bundle by the build, plus whatever a user's source tree adds. A source tree
 * that defines a standard message again (a Monas tree brings its own {@code GameStateMessage},
 * say) has its own definition used instead of the standard one.
 */
public final class StandardMessages {

	/** The runtime's .proto files, as bundled under {@code org/kse/messages/standard/}. */
	public static final List<String> FILES = List.of("Behavior.proto", "Gamecontroller.proto", "Motion.proto", "WorldInfo.proto");

	/**
	 * Where the standard files live in a catalog: the names the runtime compiles them under
	 * and a user's .proto imports them by, so that a user file called {@code WorldInfo.proto}
	 * stays a file of its own.
	 */
	public static final String FOLDER = "kse/messages/";

	/** A standard message or enum that a source tree's file defines again, by its full name. */
	public record Replacement(String type, Path standardFile, Path file) {
	}

	/**
	 * The catalog of a source tree, the standard types its files replaced (in the standard files'
	 * order), and what is wrong in the tree's own files, each named by its path in its folder.
	 */
	public record Merged(MessageCatalog catalog, List<Replacement> replacements, Map<Path, Path> userFiles) {

		/** Problems of the source tree's own .proto files, with the paths a user can open. */
		public List<ProtoProblem> problems() {
			List<ProtoProblem> problems = new ArrayList<>();
			for (ProtoProblem problem : catalog.problems()) {
				Path file = problem.file() == null ? null : userFiles.get(problem.file());
				if (file != null) {
					problems.add(new ProtoProblem(file, problem.line(), problem.column(), problem.message()));
				}
			}
			return problems;
		}
	}

	private static volatile List<ProtoFile> standard;

	private StandardMessages() {
	}

	/** The standard files, read once. */
	public static List<ProtoFile> files() {
		List<ProtoFile> result = standard;
		if (result == null) {
			standard = result = readStandard();
		}
		return result;
	}

	/** Whether a type's file is one of the standard files (as named in a catalog). */
	public static boolean isStandard(Path file) {
		if (file == null) {
			return false;
		}
		String name = file.toString().replace('\\', '/');
		return name.startsWith(FOLDER) && FILES.contains(name.substring(FOLDER.length()));
	}

	/**
	 * The standard files as fresh objects: from the data the build parsed them into (ADR 0030),
	 * or parsed here when that data is missing or was made from other texts.
	 */
	private static List<ProtoFile> readStandard() {
		return PrecomputedCatalog.bundled().orElseGet(StandardMessages::parseStandard);
	}

	/** The standard files parsed with the {@code .proto} grammar, what the build's data holds. */
	static List<ProtoFile> parseStandard() {
		List<ProtoFile> parsed = new ArrayList<>();
		for (String name : FILES) {
			parsed.add(ProtoReader.read(Path.of(FOLDER + name), text(name)));
		}
		return List.copyOf(parsed);
	}

	/**
	 * The text of a standard file as bundled, by its name in {@link #FILES} (an editor shows it,
	 * read-only: the standard files are no workspace files).
	 */
	public static String text(String name) {
		if (!FILES.contains(name)) {
			throw new IllegalArgumentException("not a standard message file: " + name);
		}
		try (InputStream in = StandardMessages.class.getResourceAsStream("standard/" + name)) {
			if (in == null) {
				throw new IllegalStateException("the KSE bundle lacks its standard message file " + name);
			}
			return new String(in.readAllBytes(), StandardCharsets.UTF_8);
		} catch (IOException e) {
			throw new UncheckedIOException(e);
		}
	}

	/** The standard messages alone. */
	public static MessageCatalog catalog() {
		return MessageCatalog.of(files());
	}

	/** {@link #merge(List)}'s catalog. */
	public static MessageCatalog catalog(List<Path> folders) {
		return merge(folders).catalog();
	}

	/**
	 * The standard messages and every {@code *.proto} under the given folders (a user's
	 * {@code messages/} folder, say). Files are named relative to their folder, so imports
	 * between them resolve as protoc would with that folder on its path. A top-level message or
	 * enum that a folder's file defines under the full name of a standard one replaces it.
	 */
	public static Merged merge(List<Path> folders) {
		return merge(folders, Set.of());
	}

	/**
	 * {@link #merge(List)} without some of the folders' files (absolute, normalized paths): what
	 * a build that leaves those files out has. A file under two of the folders is read once, under
	 * the first.
	 */
	public static Merged merge(List<Path> folders, Set<Path> leftOut) {
		SequencedMap<Path, ProtoFile> user = new LinkedHashMap<>();
		for (Path folder : folders) {
			if (!Files.isDirectory(folder)) {
				continue;
			}
			try (Stream<Path> walk = Files.walk(folder)) {
				for (Path file : walk.filter(p -> p.toString().endsWith(".proto") && Files.isRegularFile(p)).sorted().toList()) {
					if (!leftOut.contains(file.toAbsolutePath().normalize())) {
						user.putIfAbsent(file, ProtoReader.read(folder.relativize(file), readText(file)));
					}
				}
			} catch (IOException e) {
				throw new UncheckedIOException(e);
			}
		}
		return merge(user);
	}

	/**
	 * {@link #merge(List)} of files already parsed (an editor's unsaved text among them), in
	 * catalog order. Each key is where the file is on disk, what a user opens; each value was
	 * read under its path relative to its folder ({@code ProtoReader.read(folder.relativize(file), text)}),
	 * the name other files import it by. The files are linked in place: parse them afresh for
	 * each merge.
	 */
	public static Merged merge(SequencedMap<Path, ProtoFile> files) {
		if (files.isEmpty()) {
			return new Merged(catalog(), List.of(), Map.of());
		}
		List<ProtoFile> user = new ArrayList<>();
		Map<Path, Path> userFiles = new HashMap<>();
		Map<String, Path> defined = new HashMap<>();
		files.forEach((file, parsed) -> {
			userFiles.putIfAbsent(parsed.file(), file);
			user.add(parsed);
			parsed.messages().forEach(type -> defined.putIfAbsent(type.fullName(), file));
			parsed.enums().forEach(type -> defined.putIfAbsent(type.fullName(), file));
		});
		List<Replacement> replacements = new ArrayList<>();
		// Linking a catalog resolves the field types of its files in place: the shared standard
		// files must never see a user's types, so a merge that drops some works on its own copy.
		List<ProtoFile> base = files().stream().anyMatch(file -> replaces(file, defined)) ? readStandard() : files();
		List<ProtoFile> merged = new ArrayList<>();
		for (ProtoFile file : base) {
			List<MessageType> messages = new ArrayList<>();
			List<EnumType> enums = new ArrayList<>();
			for (MessageType type : file.messages()) {
				keep(type, file, defined, messages, replacements);
			}
			for (EnumType type : file.enums()) {
				keep(type, file, defined, enums, replacements);
			}
			merged.add(messages.size() == file.messages().size() && enums.size() == file.enums().size() ? file
					: new ProtoFile(file.file(), file.syntax(), file.packageName(), file.imports(), messages, enums, file.problems()));
		}
		merged.addAll(user);
		return new Merged(MessageCatalog.of(merged), List.copyOf(replacements), Map.copyOf(userFiles));
	}

	private static String readText(Path file) throws IOException {
		try {
			return Files.readString(file, StandardCharsets.UTF_8);
		} catch (MalformedInputException e) {
			throw new IOException(file + ": not a text file (it is not UTF-8)", e);
		}
	}

	private static boolean replaces(ProtoFile file, Map<String, Path> defined) {
		return file.messages().stream().anyMatch(type -> defined.containsKey(type.fullName()))
				|| file.enums().stream().anyMatch(type -> defined.containsKey(type.fullName()));
	}

	private static <T extends ProtoType> void keep(T type, ProtoFile file, Map<String, Path> defined, List<T> kept,
			List<Replacement> replacements) {
		Path replacement = defined.get(type.fullName());
		if (replacement == null) {
			kept.add(type);
		} else {
			replacements.add(new Replacement(type.fullName(), file.file(), replacement));
		}
	}
}
