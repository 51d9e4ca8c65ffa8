package org.kse.messages;

import java.util.Optional;

/**
 * A field of a message. The type is resolved once, when its file is loaded into a
 * {@link MessageCatalog}; scalar types are known right after parsing.
 */
public final class Field {

	public enum Label {
		/** Singular; also proto3 fields written without a label. */
		OPTIONAL, REQUIRED, REPEATED, MAP
	}

	private final String name;
	private final int number;
	private final Label label;
	private final String typeName;
	private final String mapKeyTypeName;
	private final String oneof;
	private final int line;
	private final int column;
	private final int typeLine;
	private final int typeColumn;
	private MessageType containingType;
	private FieldType type;

	Field(String name, int number, Label label, String typeName, String mapKeyTypeName, String oneof, int line,
			int column, int typeLine, int typeColumn) {
		this.name = name;
		this.number = number;
		this.label = label;
		this.typeName = typeName;
		this.mapKeyTypeName = mapKeyTypeName;
		this.oneof = oneof;
		this.line = line;
		this.column = column;
		this.typeLine = typeLine;
		this.typeColumn = typeColumn;
		this.type = ScalarKind.fromProtoName(typeName).<FieldType>map(FieldType.Scalar::new)
				.orElseGet(() -> new FieldType.Unresolved(typeName));
	}

	public String name() {
		return name;
	}

	/** The field number as written; 0 when it was missing or not a number (a problem says so). */
	public int number() {
		return number;
	}

	public Label label() {
		return label;
	}

	public boolean isRepeated() {
		return label == Label.REPEATED || label == Label.MAP;
	}

	/** The type as written ({@code Position}, {@code .pkg.Outer.Inner}, {@code int32}); for a map, its value type. */
	public String typeName() {
		return typeName;
	}

	/** For a map field, the key type as written (always a scalar keyword). */
	public Optional<String> mapKeyTypeName() {
		return Optional.ofNullable(mapKeyTypeName);
	}

	/** The name of the enclosing {@code oneof}, or "" when the field is not part of one. */
	public String oneof() {
		return oneof;
	}

	/** Position of the field name. */
	public int line() {
		return line;
	}

	public int column() {
		return column;
	}

	/** Position of the type name, where an unknown type is reported. */
	public int typeLine() {
		return typeLine;
	}

	public int typeColumn() {
		return typeColumn;
	}

	public MessageType containingType() {
		return containingType;
	}

	/** For a map field, the value type. */
	public FieldType type() {
		return type;
	}

	public Optional<ScalarKind> scalarKind() {
		return type instanceof FieldType.Scalar s ? Optional.of(s.kind()) : Optional.empty();
	}

	public Optional<MessageType> messageType() {
		return type instanceof FieldType.Message m ? Optional.of(m.type()) : Optional.empty();
	}

	public Optional<EnumType> enumType() {
		return type instanceof FieldType.Enum e ? Optional.of(e.type()) : Optional.empty();
	}

	public boolean isResolved() {
		return !(type instanceof FieldType.Unresolved);
	}

	void setContainingType(MessageType containingType) {
		this.containingType = containingType;
	}

	void resolve(FieldType resolved) {
		this.type = resolved;
	}

	@Override
	public String toString() {
		String typeText = mapKeyTypeName == null ? typeName : "map<" + mapKeyTypeName + ", " + typeName + ">";
		String labelText = label == Label.MAP ? "" : label.name().toLowerCase(java.util.Locale.ROOT) + " ";
		return labelText + typeText + " " + name + " = " + number;
	}
}
