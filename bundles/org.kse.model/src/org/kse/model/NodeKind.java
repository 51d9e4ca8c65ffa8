package org.kse.model;

import org.kse.model.statechart.Node;

/**
 * The six kinds of statechart node. The metamodel keeps the kind as a string
 * ({@code Node.type}) for compatibility with files of the original tool.
 */
public enum NodeKind {
	OR, AND, BASIC, START, END, CONDITION;

	/** The kind of a node, or null when its type string is missing or unknown. */
	public static NodeKind of(Node node) {
		String type = node.getType();
		if (type == null) {
			return null;
		}
		for (NodeKind kind : values()) {
			if (kind.name().equals(type)) {
				return kind;
			}
		}
		return null;
	}

	public boolean is(Node node) {
		return name().equals(node.getType());
	}

	/** START, END and CONDITION: the states that the tool names by their label. */
	public boolean isAuxiliary() {
		return this == START || this == END || this == CONDITION;
	}

	/** OR and AND: the states that hold other states. */
	public boolean isComposite() {
		return this == OR || this == AND;
	}
}
