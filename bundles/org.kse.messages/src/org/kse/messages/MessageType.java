package org.kse.messages;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Optional;

/** A message declaration; identity is the declaration itself, not its name. */
public final class MessageType implements ProtoType {

	private final String name;
	private String fullName;
	private final Path file;
	private final int line;
	private final int column;
	private final MessageType parent;
	private final List<Field> fields = new ArrayList<>();
	private final List<MessageType> nestedMessages = new ArrayList<>();
	private final List<EnumType> nestedEnums = new ArrayList<>();

	MessageType(String name, String fullName, Path file, int line, int column, MessageType parent) {
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

	/** Package, enclosing messages and name joined by dots, e.g. {@code WorldInfo.Position}. */
	@Override
	public String fullName() {
		return fullName;
	}

	@Override
	public Path file() {
		return file;
	}

	/** Position of the message name. */
	@Override
	public int line() {
		return line;
	}

	@Override
	public int column() {
		return column;
	}

	/** The enclosing message, or empty for a top-level message. */
	@Override
	public Optional<MessageType> parent() {
		return Optional.ofNullable(parent);
	}

	/** Fields in declaration order, including those inside oneofs. */
	public List<Field> fields() {
		return Collections.unmodifiableList(fields);
	}

	public Optional<Field> field(String fieldName) {
		return fields.stream().filter(f -> f.name().equals(fieldName)).findFirst();
	}

	public List<MessageType> nestedMessages() {
		return Collections.unmodifiableList(nestedMessages);
	}

	public List<EnumType> nestedEnums() {
		return Collections.unmodifiableList(nestedEnums);
	}

	void addField(Field field) {
		field.setContainingType(this);
		fields.add(field);
	}

	void addMessage(MessageType message) {
		nestedMessages.add(message);
	}

	void addEnum(EnumType enumType) {
		nestedEnums.add(enumType);
	}

	/** The package statement may follow the declarations, so names are qualified after parsing. */
	void qualify(String packageName) {
		fullName = packageName + "." + fullName;
	}

	@Override
	public String toString() {
		return "message " + fullName;
	}
}
