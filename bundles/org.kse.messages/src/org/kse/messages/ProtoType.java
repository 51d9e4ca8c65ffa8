package org.kse.messages;

import java.nio.file.Path;
import java.util.Optional;

/** A named type declared in a {@code .proto} file: what a field's type name can refer to. */
public sealed interface ProtoType permits MessageType, EnumType {

	String name();

	/** Package, enclosing messages and name joined by dots. */
	String fullName();

	Path file();

	/** Position of the type's name. */
	int line();

	int column();

	/** The enclosing message, or empty at the top level of a file. */
	Optional<MessageType> parent();
}
