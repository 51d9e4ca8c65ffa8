package org.kse.messages;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.Function;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * The message types the statechart validator and the C++ generator may refer to: every
 * {@code .proto} file under some folders, parsed and linked.
 *
 * <p>
 * Loading never fails; unreadable files, syntax errors, unknown types and duplicate names end up
 * in {@link #problems()}. Everything is ordered by root, then relative path, then declaration,
 * so the same folders always give the same catalog and the same problems.
 */
public final class MessageCatalog {

	private static final List<String> STANDARD_TOPICS = List.of("behavior", "worldstate", "vision", "motion",
			"sensors", "communication", "obstacle", "external", "buttonevents");

	private final List<ProtoFile> files;
	private final List<MessageType> messages = new ArrayList<>();
	private final List<EnumType> enums = new ArrayList<>();
	private final Map<String, ProtoType> typesByFullName;
	private final Set<String> enumValues = new HashSet<>();
	/** Ambiguous look-ups are found while answering queries, hence a list that may still grow. */
	private final List<ProtoProblem> problems;
	private final Set<String> reportedAmbiguities = new HashSet<>();

	private MessageCatalog(List<TypeResolver.Unit> units, List<ProtoProblem> loadProblems) {
		this.files = units.stream().map(TypeResolver.Unit::file).toList();
		List<ProtoProblem> found = new ArrayList<>();
		files.forEach(f -> found.addAll(f.problems()));
		this.typesByFullName = TypeResolver.resolve(units, found);
		sortByFileAndPosition(found);
		List<ProtoProblem> all = new ArrayList<>(loadProblems);
		all.addAll(found);
		this.problems = Collections.synchronizedList(all);
		for (ProtoType type : typesByFullName.values()) {
			switch (type) {
			case MessageType m -> messages.add(m);
			case EnumType e -> {
				enums.add(e);
				enumValues.addAll(e.values().keySet());
			}
			}
		}
	}

	/**
	 * Reads every {@code *.proto} file under the given folders (recursively). A root that is itself
	 * a {@code .proto} file is read as well. Imports are matched against paths relative to the roots.
	 */
	public static MessageCatalog load(List<Path> roots) {
		List<ProtoProblem> loadProblems = new ArrayList<>();
		List<TypeResolver.Unit> units = new ArrayList<>();
		Set<Path> seen = new HashSet<>();
		for (Path root : roots) {
			for (Path file : protoFiles(root, loadProblems)) {
				if (!seen.add(file.toAbsolutePath().normalize())) {
					continue; // overlapping roots
				}
				String importName = Files.isDirectory(root) ? slashed(root.relativize(file))
						: String.valueOf(file.getFileName());
				try {
					String text = new String(Files.readAllBytes(file), StandardCharsets.UTF_8);
					units.add(new TypeResolver.Unit(ProtoReader.read(file, text), importName));
				} catch (IOException | RuntimeException e) {
					loadProblems.add(new ProtoProblem(file, 1, 1, "cannot read file: " + e));
				}
			}
		}
		return new MessageCatalog(units, loadProblems);
	}

	/** A catalog of files parsed elsewhere (an editor's buffers, tests); imports match the file paths. */
	public static MessageCatalog of(List<ProtoFile> files) {
		List<TypeResolver.Unit> units = files.stream()
				.map(f -> new TypeResolver.Unit(f, f.file() == null ? "" : slashed(f.file().normalize()))).toList();
		return new MessageCatalog(units, List.of());
	}

	/** The topics Monas components publish on; the default set, to which users may add their own. */
	public static List<String> standardTopics() {
		return STANDARD_TOPICS;
	}

	/**
	 * A message by full name ({@code pkg.Outer.Inner}), by a trailing part of it
	 * ({@code Outer.Inner}), or by simple name. Top-level messages win over nested ones of the
	 * same name; if several remain, the look-up is reported as a problem once and the first in
	 * catalog order is returned.
	 */
	public Optional<MessageType> message(String name) {
		return lookup(name, MessageType.class, messages);
	}

	/** An enum, looked up like {@link #message(String)}. */
	public Optional<EnumType> enumType(String name) {
		return lookup(name, EnumType.class, enums);
	}

	/** Every message, nested ones included, in catalog order (file, then declaration, depth first). */
	public Collection<MessageType> messages() {
		return Collections.unmodifiableList(messages);
	}

	/** Every enum, nested ones included, in catalog order. */
	public Collection<EnumType> enums() {
		return Collections.unmodifiableList(enums);
	}

	public List<ProtoFile> files() {
		return files;
	}

	/** A snapshot: load problems first, then per file in catalog order by position, then ambiguous look-ups. */
	public List<ProtoProblem> problems() {
		synchronized (problems) {
			return List.copyOf(problems);
		}
	}

	/**
	 * Whether some enum defines this constant, e.g. {@code PLAYER_PLAYING}; a qualified
	 * {@code PlayerState.PLAYER_PLAYING} must be defined by that enum.
	 */
	public boolean hasEnumValue(String constant) {
		int dot = constant.lastIndexOf('.');
		if (dot < 0) {
			return enumValues.contains(constant);
		}
		return enumType(constant.substring(0, dot)).map(e -> e.values().containsKey(constant.substring(dot + 1)))
				.orElse(false);
	}

	/**
	 * Follows a member path through singular message fields, e.g. WorldInfo + [myPosition, x] gives
	 * the field x of myPosition's type. Empty when a name is not a field, or when the path goes on
	 * past a scalar, an enum, a repeated or a map field (those need an index first).
	 */
	public Optional<Field> resolveMember(MessageType type, List<String> memberNames) {
		if (type == null || memberNames.isEmpty()) {
			return Optional.empty();
		}
		MessageType current = type;
		Field field = null;
		for (String name : memberNames) {
			if (current == null) {
				return Optional.empty();
			}
			field = current.field(name).orElse(null);
			if (field == null) {
				return Optional.empty();
			}
			current = field.isRepeated() ? null : field.messageType().orElse(null);
		}
		return Optional.of(field);
	}

	private <T extends ProtoType> Optional<T> lookup(String name, Class<T> kind, List<T> all) {
		String wanted = name.startsWith(".") ? name.substring(1) : name;
		ProtoType exact = typesByFullName.get(wanted);
		if (kind.isInstance(exact)) {
			return Optional.of(kind.cast(exact));
		}
		List<T> matches = all.stream()
				.filter(t -> t.name().equals(wanted) || t.fullName().endsWith("." + wanted)).toList();
		List<T> topLevel = matches.stream().filter(t -> t.parent().isEmpty()).toList();
		List<T> pool = topLevel.isEmpty() ? matches : topLevel;
		if (pool.size() > 1) {
			reportAmbiguity(wanted, pool);
		}
		return pool.stream().findFirst();
	}

	private void reportAmbiguity(String name, List<? extends ProtoType> pool) {
		synchronized (problems) {
			if (!reportedAmbiguities.add(pool.get(0).getClass().getSimpleName() + ":" + name)) {
				return;
			}
			ProtoType second = pool.get(1);
			String all = pool.stream().map(t -> t.fullName() + " (" + TypeResolver.position(t) + ")")
					.collect(Collectors.joining(", "));
			problems.add(new ProtoProblem(second.file(), second.line(), second.column(),
					"the name " + name + " is ambiguous: " + all + "; using " + pool.get(0).fullName()));
		}
	}

	private void sortByFileAndPosition(List<ProtoProblem> list) {
		Map<Path, Integer> order = new HashMap<>();
		for (ProtoFile f : files) {
			order.putIfAbsent(f.file(), order.size());
		}
		Function<ProtoProblem, Integer> fileIndex = p -> order.getOrDefault(p.file(), Integer.MAX_VALUE);
		list.sort(Comparator.comparing(fileIndex).thenComparingInt(ProtoProblem::line)
				.thenComparingInt(ProtoProblem::column));
	}

	private static List<Path> protoFiles(Path root, List<ProtoProblem> loadProblems) {
		if (Files.isRegularFile(root)) {
			return List.of(root);
		}
		if (!Files.isDirectory(root)) {
			loadProblems.add(new ProtoProblem(root, 1, 1, "message folder not found: " + root));
			return List.of();
		}
		try (Stream<Path> walk = Files.walk(root)) {
			return walk.filter(p -> p.getFileName().toString().endsWith(".proto") && Files.isRegularFile(p))
					.sorted(Comparator.comparing(p -> slashed(root.relativize(p)))).toList();
		} catch (IOException | UncheckedIOException e) {
			loadProblems.add(new ProtoProblem(root, 1, 1, "cannot list message folder: " + e.getMessage()));
			return List.of();
		}
	}

	/** Paths as protoc import names: '/'-separated on every platform. */
	private static String slashed(Path path) {
		return path.toString().replace(path.getFileSystem().getSeparator(), "/");
	}
}
