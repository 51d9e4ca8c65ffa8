package org.kse.messages;

import java.util.Optional;

/** The protobuf scalar value types. */
public enum ScalarKind {
	DOUBLE, FLOAT, INT32, INT64, UINT32, UINT64, SINT32, SINT64, FIXED32, FIXED64, SFIXED32, SFIXED64, BOOL,
	STRING, BYTES;

	/** The keyword as written in a {@code .proto} file, e.g. "int32". */
	public String protoName() {
		return name().toLowerCase(java.util.Locale.ROOT);
	}

	/** Map keys may be any integral or string type, never floating point, bytes or a message. */
	public boolean isValidMapKey() {
		return this != DOUBLE && this != FLOAT && this != BYTES;
	}

	public static Optional<ScalarKind> fromProtoName(String name) {
		for (ScalarKind kind : values()) {
			if (kind.protoName().equals(name)) {
				return Optional.of(kind);
			}
		}
		return Optional.empty();
	}
}
