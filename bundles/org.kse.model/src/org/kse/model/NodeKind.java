package org.kse.model;

import org.kse.model.statechart.Node;

/**
 * The six kinds of statechart node. The metamodel keeps the kind as a string
 * ({@code Node.type}) for compatibility with files of the original tool.
 */
public enum NodeKind {
	OR("OR (sequence)", "symbol-namespace"),
	AND("AND (parallel)", "split-horizontal"),
	BASIC("Basic (activity)", "symbol-method"),
	START("Start", "circle-filled"),
	END("End", "record"),
	CONDITION("Condition", "circle-large-outline");

	/** The order in which the thesis introduces the kinds, and the palette offers them. */
	public static final java.util.List<NodeKind> THESIS_ORDER = java.util.List.of(START, END, CONDITION, BASIC, OR, AND);

	private final String caption;
	private final String icon;

	NodeKind(String caption, String icon) {
		this.caption = caption;
		this.icon = icon;
	}

	/** What a user reads for this kind in a palette or a menu. */
	public String caption() {
		return caption;
	}

	/** The codicon that stands for this kind in a palette. */
	public String icon() {
		return icon;
	}

	/** The kind named by a type string ({@code Node.type}), or null when it names none. */
	public static NodeKind of(String type) {
		for (NodeKind kind : values()) {
			if (kind.name().equals(type)) {
				return kind;
			}
		}
		return null;
	}

	/** The kind of a node, or null when its type string is missing or unknown. */
	public static NodeKind of(Node node) {
		return of(node.getType());
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
