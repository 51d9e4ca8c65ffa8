package org.kse.generator.monas;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.stream.Stream;

import org.kse.messages.ProtoFile;
import org.kse.messages.ProtoReader;
import org.kse.messages.StandardMessages;

/**
 * The .proto files of a source tree's {@code messages/} folder, as the generated CMake builds
 * them. A file that defines a standard message again (a Monas tree's own
 * {@code GameStateMessage}) cannot be compiled next to the runtime's {@code kse::messages},
 * which every program links and which holds a C++ type of that name already: such a file is
 * left out, and the generated code uses the runtime's type.
 *
 * @param compiled  files built into {@code kse_user_messages}, relative to the folder, sorted
 * @param replacing files left out, with the standard types each defines again
 * @param alongside of the files left out, those that define other types too, with those types
 *                  (the generated CMake stops on them: those types would be missing)
 * @param replaced  every standard type the tree's files replace, by full name
 */
public record TreeMessages(List<String> compiled, Map<String, List<String>> replacing, Map<String, List<String>> alongside,
		Set<String> replaced) {

	public static final TreeMessages NONE = new TreeMessages(List.of(), Map.of(), Map.of(), Set.of());

	/** The files under {@code folder}, sorted out by the replacements a merged catalog found. */
	public static TreeMessages of(Path folder, List<StandardMessages.Replacement> replacements) throws IOException {
		if (!Files.isDirectory(folder)) {
			return NONE;
		}
		Path root = folder.toAbsolutePath().normalize();
		Map<String, List<String>> replacing = new TreeMap<>();
		Set<String> replaced = new TreeSet<>();
		for (StandardMessages.Replacement replacement : replacements) {
			replaced.add(replacement.type());
			Path file = replacement.file().toAbsolutePath().normalize();
			if (file.startsWith(root)) {
				replacing.computeIfAbsent(slashed(root.relativize(file)), key -> new ArrayList<>()).add(replacement.type());
			}
		}
		List<String> compiled = new ArrayList<>();
		Map<String, List<String>> alongside = new TreeMap<>();
		try (Stream<Path> walk = Files.walk(root)) {
			for (Path file : walk.filter(p -> p.toString().endsWith(".proto") && Files.isRegularFile(p)).sorted().toList()) {
				String name = slashed(root.relativize(file));
				List<String> again = replacing.get(name);
				if (again == null) {
					compiled.add(name);
					continue;
				}
				ProtoFile parsed = ProtoReader.read(file, Files.readString(file, StandardCharsets.UTF_8));
				List<String> others = Stream.concat(parsed.messages().stream().map(type -> type.fullName()), parsed.enums().stream().map(type -> type.fullName()))
						.filter(type -> !again.contains(type)).toList();
				if (!others.isEmpty()) {
					alongside.put(name, others);
				}
			}
		}
		compiled.sort(null);
		return new TreeMessages(List.copyOf(compiled), Collections.unmodifiableMap(replacing), Collections.unmodifiableMap(alongside), Set.copyOf(replaced));
	}

	private static String slashed(Path path) {
		return path.toString().replace(path.getFileSystem().getSeparator(), "/");
	}
}
