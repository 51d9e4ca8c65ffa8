package org.kse.messages;

import java.nio.file.Path;
import java.util.Optional;

/**
 * A named type declared in a {@code .proto} file: what a field's type name can refer to.
 * Identity is the declaration itself, not its name.
 */
public abstract sealed class ProtoType permits MessageType, EnumType {

	private final String name;
	private String fullName;
	private final Path file;
	private final int line;
	private final int column;
	private final MessageType parent;

	ProtoType(String name, String fullName, Path file, int line, int column, MessageType parent) {
		this.name = name;
		this.fullName = fullName;
		this.file = file;
		this.line = line;
		this.column = column;
		this.parent = parent;
	}

	public String name() {
		return name;
	}

	/** Package, enclosing messages and name joined by dots, e.g. {@code WorldInfo.Position}. */
	public String fullName() {
		return fullName;
	}

	public Path file() {
		return file;
	}

	/** Position of the type's name. */
	public int line() {
		return line;
	}

	public int column() {
		return column;
	}

	/** The enclosing message, or empty at the top level of a file. */
	public Optional<MessageType> parent() {
		return Optional.ofNullable(parent);
	}

	/** The package statement may follow the declarations, so names are qualified after parsing. */
	void qualify(String packageName) {
		fullName = packageName + "." + fullName;
	}
}
