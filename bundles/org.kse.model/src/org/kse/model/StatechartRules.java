package org.kse.model;

import java.util.EnumSet;
import java.util.Set;

/**
 * The structural rules of a KSE statechart, kept in one place: which kind of state may hold
 * which, which may start or end a transition, what the root is, how many START and END states an
 * OR state has. The validator, the edit commands, the diagram server (type hints, palette, create,
 * paste, reparent) and the tree editor ask here; each refusal is a sentence a user can act on.
 *
 * <p>The C++ runtime checks the same rules on its own (it is a library of its own); its list of
 * kinds is tested against {@link NodeKind}.
 */
public final class StatechartRules {

	/** An OR state has exactly this many START states. */
	public static final int STARTS_PER_OR = 1;

	/** An OR state has at most this many END states. */
	public static final int MAX_ENDS_PER_OR = 1;

	private StatechartRules() {
	}

	/** The kinds a state of this kind may hold: any in an OR state, OR regions in an AND state, none in the others. */
	public static Set<NodeKind> mayHold(NodeKind parent) {
		return switch (parent) {
			case OR -> EnumSet.allOf(NodeKind.class);
			case AND -> EnumSet.of(NodeKind.OR);
			default -> EnumSet.noneOf(NodeKind.class);
		};
	}

	/** Why a {@code child} state cannot go into a {@code parent} state, or null when it can. */
	public static String holdRefusal(NodeKind parent, NodeKind child) {
		if (mayHold(parent).contains(child)) {
			return null;
		}
		if (parent.isComposite()) {
			return "an " + parent + " state holds only " + names(mayHold(parent)) + " regions, not " + child + " states";
		}
		return leafRefusal(parent);
	}

	/** Why a state of this kind cannot hold any state, or null when it may hold some. */
	public static String leafRefusal(NodeKind kind) {
		return mayHold(kind).isEmpty() ? article(kind) + " " + kind + " state cannot hold other states" : null;
	}

	/** Why a state of this type ({@code Node.type}) cannot be the root of a model, or null when it can (only an OR state can). */
	public static String rootRefusal(String type) {
		return NodeKind.of(type) == NodeKind.OR ? null : "the root state must be an OR state, not " + (type == null ? "a state without a type" : type);
	}

	/** Whether a transition may end in a state of this kind: in any but START. */
	public static boolean mayEnter(NodeKind target) {
		return target != NodeKind.START;
	}

	/** Whether a transition may start in a state of this kind: in any but END. */
	public static boolean mayLeave(NodeKind source) {
		return source != NodeKind.END;
	}

	/** Why no transition may run from {@code source} to {@code target}, or null when one may. */
	public static String transitionRefusal(NodeKind source, NodeKind target) {
		if (source != null && !mayLeave(source)) {
			return "no transition leaves " + article(source) + " " + source + " state";
		}
		if (target != null && !mayEnter(target)) {
			return "no transition enters " + article(target) + " " + target + " state";
		}
		return null;
	}

	/** Why an OR state with this many START states is wrong, or null when it is right. */
	public static String startCountRefusal(long starts) {
		return starts == STARTS_PER_OR ? null : "an OR state needs exactly one START state; it has " + starts;
	}

	/** Why an OR state with this many END states is wrong, or null when it is right. */
	public static String endCountRefusal(long ends) {
		return ends <= MAX_ENDS_PER_OR ? null : "an OR state has at most one END state; it has " + ends;
	}

	/** Whether a user may resize a state of this kind in a diagram: composites and BASIC boxes; discs keep their size. */
	public static boolean isResizable(NodeKind kind) {
		return kind.isComposite() || kind == NodeKind.BASIC;
	}

	private static String names(Set<NodeKind> kinds) {
		return String.join(" or ", kinds.stream().map(NodeKind::name).toList());
	}

	private static String article(NodeKind kind) {
		return "AEIOU".indexOf(kind.name().charAt(0)) >= 0 ? "an" : "a";
	}
}
