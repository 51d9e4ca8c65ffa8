package org.kse.messages;

import java.nio.file.Path;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;

/** An enum declaration with its values in declaration order. */
public final class EnumType implements ProtoType {

	private final String name;
	private String fullName;
	private final Path file;
	private final int line;
	private final int column;
	private final MessageType parent;
	private final Map<String, Integer> values = new LinkedHashMap<>();

	EnumType(String name, String fullName, Path file, int line, int column, MessageType parent) {
		this.name = name;
		this.fullName = fullName;
		this.file = file;
		this.line = line;
		this.column = column;
		this.parent = parent;
	}

	@Override
	public String name() {
		return name;
	}

	@Override
	public String fullName() {
		return fullName;
	}

	@Override
	public Path file() {
		return file;
	}

	@Override
	public int line() {
		return line;
	}

	@Override
	public int column() {
		return column;
	}

	/** The enclosing message, or empty for a top-level enum. */
	@Override
	public Optional<MessageType> parent() {
		return Optional.ofNullable(parent);
	}

	/** Value name to number, in declaration order. */
	public Map<String, Integer> values() {
		return Collections.unmodifiableMap(values);
	}

	public OptionalInt value(String valueName) {
		Integer number = values.get(valueName);
		return number == null ? OptionalInt.empty() : OptionalInt.of(number);
	}

	/** @return false when the name was already taken (the first number is kept) */
	boolean addValue(String valueName, int number) {
		return values.putIfAbsent(valueName, number) == null;
	}

	/** The package statement may follow the declarations, so names are qualified after parsing. */
	void qualify(String packageName) {
		fullName = packageName + "." + fullName;
	}

	@Override
	public String toString() {
		return "enum " + fullName;
	}
}
