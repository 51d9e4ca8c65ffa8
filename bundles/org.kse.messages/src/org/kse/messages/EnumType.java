package org.kse.messages;

import java.nio.file.Path;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.OptionalInt;

/** An enum declaration with its values in declaration order. */
public final class EnumType extends ProtoType {

	private final Map<String, Integer> values = new LinkedHashMap<>();

	EnumType(String name, String fullName, Path file, int line, int column, MessageType parent) {
		super(name, fullName, file, line, column, parent);
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

	@Override
	public String toString() {
		return "enum " + fullName();
	}
}
