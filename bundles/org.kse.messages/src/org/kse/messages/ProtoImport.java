package org.kse.messages;

/** An {@code import} statement: the path as written and where it stands. */
public record ProtoImport(String path, Modifier modifier, int line, int column) {

	public enum Modifier {
		NONE, PUBLIC, WEAK
	}
}
