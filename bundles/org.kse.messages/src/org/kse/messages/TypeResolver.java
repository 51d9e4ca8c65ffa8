package org.kse.messages;

import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.Collections;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * Links the parsed files of a catalog: finds imported files, registers every type by full name
 * (reporting duplicates) and resolves field type names with protobuf's scoping (innermost
 * enclosing scope first, then outwards to the package root).
 */
final class TypeResolver {

	/** A parsed file with the name other files import it by (its path relative to its root, with '/'). */
	record Unit(ProtoFile file, String importName) {
	}

	private final List<Unit> units;
	private final List<ProtoProblem> problems;
	private final Map<String, ProtoType> types = new LinkedHashMap<>();
	/** Found imports per unit; identity keys, as two units may hold equal content. */
	private final Map<Unit, List<Link>> links = new IdentityHashMap<>();

	private record Link(ProtoImport statement, Unit target) {
	}

	private TypeResolver(List<Unit> units, List<ProtoProblem> problems) {
		this.units = units;
		this.problems = problems;
	}

	/** @return every type by full name, in file and declaration order (first declaration wins) */
	static Map<String, ProtoType> resolve(List<Unit> units, List<ProtoProblem> problems) {
		TypeResolver resolver = new TypeResolver(units, problems);
		units.forEach(resolver::register);
		units.forEach(resolver::findImports);
		units.forEach(resolver::resolveFields);
		return resolver.types;
	}

	private void register(Unit unit) {
		for (MessageType m : unit.file().messages()) {
			registerMessage(m);
		}
		for (EnumType e : unit.file().enums()) {
			registerType(e);
		}
	}

	private void registerMessage(MessageType message) {
		registerType(message);
		message.nestedMessages().forEach(this::registerMessage);
		message.nestedEnums().forEach(this::registerType);
	}

	private void registerType(ProtoType type) {
		ProtoType first = types.putIfAbsent(type.fullName(), type);
		if (first != null) {
			report(type.file(), type.line(), type.column(), "duplicate type name " + type.fullName()
					+ ", already defined at " + position(first));
		}
	}

	private void findImports(Unit unit) {
		List<Link> found = new ArrayList<>();
		for (ProtoImport imp : unit.file().imports()) {
			Optional<Unit> target = findImport(unit, imp.path());
			if (target.isPresent()) {
				found.add(new Link(imp, target.get()));
			} else if (imp.modifier() != ProtoImport.Modifier.WEAK) {
				report(unit.file().file(), imp.line(), imp.column(), "imported file \"" + imp.path() + "\" not found");
			}
		}
		links.put(unit, found);
	}

	/**
	 * By name relative to a root (as protoc's -I would), then relative to the importing file, then
	 * by a unique path suffix, which forgives imports written against a different root.
	 */
	private Optional<Unit> findImport(Unit importer, String path) {
		String wanted = path.replace('\\', '/');
		for (Unit u : units) {
			if (u.importName().equals(wanted)) {
				return Optional.of(u);
			}
		}
		Path dir = importer.file().file() == null ? null : importer.file().file().getParent();
		if (dir != null) {
			Path sibling = dir.resolve(wanted).normalize();
			for (Unit u : units) {
				if (u.file().file() != null && u.file().file().normalize().equals(sibling)) {
					return Optional.of(u);
				}
			}
		}
		List<Unit> bySuffix = units.stream().filter(u -> u.importName().endsWith("/" + wanted)).toList();
		return bySuffix.size() == 1 ? Optional.of(bySuffix.get(0)) : Optional.empty();
	}

	/** The unit itself, its direct imports, and whatever those re-export with {@code import public}. */
	private Set<Path> visibleFiles(Unit unit) {
		Set<Path> visible = new HashSet<>();
		visible.add(unit.file().file());
		Set<Unit> done = Collections.newSetFromMap(new IdentityHashMap<>());
		Deque<Unit> todo = new ArrayDeque<>();
		links.get(unit).forEach(link -> todo.push(link.target()));
		while (!todo.isEmpty()) {
			Unit u = todo.pop();
			if (done.add(u)) {
				visible.add(u.file().file());
				links.get(u).stream().filter(link -> link.statement().modifier() == ProtoImport.Modifier.PUBLIC)
						.forEach(link -> todo.push(link.target()));
			}
		}
		return visible;
	}

	private void resolveFields(Unit unit) {
		Set<Path> visible = visibleFiles(unit);
		Deque<MessageType> todo = new ArrayDeque<>(unit.file().messages());
		while (!todo.isEmpty()) {
			MessageType message = todo.pop();
			message.nestedMessages().forEach(todo::push);
			for (Field field : message.fields()) {
				if (field.type() instanceof FieldType.Unresolved unresolved) {
					resolveField(field, unresolved.name(), message, unit, visible);
				}
			}
		}
	}

	private void resolveField(Field field, String typeName, MessageType scope, Unit unit, Set<Path> visible) {
		ProtoType hidden = null;
		for (String candidate : candidates(typeName, scope.fullName())) {
			ProtoType type = types.get(candidate);
			if (type == null) {
				continue;
			}
			if (visible.contains(type.file())) {
				field.resolve(toFieldType(type));
				return;
			}
			if (hidden == null) {
				hidden = type;
			}
		}
		Path file = unit.file().file();
		if (hidden != null) {
			// Keep going with the type, but protoc would refuse this file.
			field.resolve(toFieldType(hidden));
			report(file, field.typeLine(), field.typeColumn(), "type " + typeName + " is defined in "
					+ fileName(hidden.file()) + ", which " + fileName(file) + " does not import");
			return;
		}
		report(file, field.typeLine(), field.typeColumn(),
				"unknown type " + typeName + " of field " + field.name() + " in message " + scope.name());
	}

	/** Full names to try for {@code typeName} used inside message {@code scope}, innermost first. */
	static List<String> candidates(String typeName, String scope) {
		if (typeName.startsWith(".")) {
			return List.of(typeName.substring(1));
		}
		List<String> result = new ArrayList<>();
		String s = scope;
		while (!s.isEmpty()) {
			result.add(s + "." + typeName);
			int dot = s.lastIndexOf('.');
			s = dot < 0 ? "" : s.substring(0, dot);
		}
		result.add(typeName);
		return result;
	}

	private static FieldType toFieldType(ProtoType type) {
		return switch (type) {
		case MessageType m -> new FieldType.Message(m);
		case EnumType e -> new FieldType.Enum(e);
		};
	}

	private void report(Path file, int line, int column, String message) {
		problems.add(new ProtoProblem(file, line, column, message));
	}

	static String position(ProtoType type) {
		return fileName(type.file()) + ":" + type.line() + ":" + type.column();
	}

	private static String fileName(Path file) {
		return file == null ? "<unknown>" : String.valueOf(file.getFileName());
	}
}
