package org.kse.messages;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Optional;

/** A message declaration; identity is the declaration itself, not its name. */
public final class MessageType extends ProtoType {

	private final List<Field> fields = new ArrayList<>();
	private final List<MessageType> nestedMessages = new ArrayList<>();
	private final List<EnumType> nestedEnums = new ArrayList<>();

	MessageType(String name, String fullName, Path file, int line, int column, MessageType parent) {
		super(name, fullName, file, line, column, parent);
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

	@Override
	public String toString() {
		return "message " + fullName();
	}
}
