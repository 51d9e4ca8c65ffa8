package org.kse.messages;

/** What a field holds, once its type name has been looked up. */
public sealed interface FieldType {

	record Scalar(ScalarKind kind) implements FieldType {
	}

	record Message(MessageType type) implements FieldType {
	}

	record Enum(EnumType type) implements FieldType {
	}

	/** A type name that could not be (or has not yet been) found, as written. */
	record Unresolved(String name) implements FieldType {
	}
}
