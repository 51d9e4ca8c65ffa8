package org.kse.model;

import java.io.IOException;
import java.io.OutputStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.InternalEObject;
import org.eclipse.emf.ecore.util.InternalEList;
import org.kse.model.StctReader.NotOurs;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.StatechartPackage;
import org.kse.model.statechart.Transition;
import org.kse.model.statechart.Variable;

/**
 * Writes a model as the bytes EMF's XMI serializer writes with {@code StatechartResources}' save
 * options (ADR 0026): ASCII with character references, two spaces of indentation per level, the
 * attributes in the metamodel's order, unset values left out, references as positional paths,
 * the JVM's line separator. It writes only what it is sure of: an element of another class, a
 * proxy, a reference that leaves the model, or text EMF would refuse raises {@link NotOurs} before
 * a byte is written, and the caller lets EMF save (and report) instead.
 */
final class StctWriter {

	private static final byte[] HEADER = ascii("<?xml version=\"1.0\" encoding=\"ASCII\"?>");
	private static final byte[] ROOT = ascii("<statechart:Model xmi:version=\"2.0\" xmlns:xmi=\"http://www.omg.org/XMI\" xmlns:statechart=\""
			+ StatechartPackage.eNS_URI + "\"");
	private static final byte[] ROOT_END = ascii("</statechart:Model>");
	private static final byte[] NODES = ascii("nodes");
	private static final byte[] CHILDREN = ascii("Children");
	private static final byte[] TRANSITIONS = ascii("transitions");
	private static final byte[] VARIABLES = ascii("variables");
	private static final byte[] VARIABLE_PATH = ascii("//@variables.");
	private static final byte[] NODE_PATH = ascii("//@nodes.");
	private static final byte[] CHILD_PATH = ascii("/@Children.");
	private static final byte[] HEX = ascii("0123456789abcdef");
	/** Each attribute's {@code  name="}, written with one copy. */
	private static final byte[] NAME = opening("name");
	private static final byte[] LABEL = opening("label");
	private static final byte[] TYPE = opening("type");
	private static final byte[] ACTIVITY = opening("activity");
	private static final byte[] TE = opening("TE");
	private static final byte[] SOURCE = opening("source");
	private static final byte[] TARGET = opening("target");
	private static final byte[] STATE_VARIABLES = opening("variables");

	private final byte[] lineSeparator;
	/**
	 * The text written so far: full chunks and the one being filled. Chunks, not one growing
	 * array, so that a large model costs no copies and no huge allocations.
	 */
	private final List<byte[]> chunks = new ArrayList<>();
	private final List<Integer> chunkSizes = new ArrayList<>();
	/** Chunks of earlier saves, used before new ones are made. */
	private final java.util.ArrayDeque<byte[]> spare = SpareBuffers.takeChunks();
	private byte[] out = SpareBuffers.chunk(spare);
	private int size;

	/** Each state's positional path, made when {@link #lastPath} does not find a transition's end; each variable's. */
	private StatePaths statePaths;
	/** The path of the state last written as a transition's end, and of each state above it. */
	private final LastPath lastPath = new LastPath();
	private final Map<Variable, byte[]> variablePaths = new IdentityHashMap<>();
	private final Model model;

	private StctWriter(Model model, String lineSeparator) {
		this.lineSeparator = ascii(lineSeparator);
		this.scanBudget = 16L * (model.getTransitions().size() + 64);
		this.model = model;
	}

	/**
	 * Writes the model to {@code output}; nothing is written when it raises {@link NotOurs}, as
	 * the whole text is made before the first byte goes out.
	 */
	static void write(Model model, String lineSeparator, OutputStream output) throws NotOurs, IOException {
		StctWriter writer = new StctWriter(model, lineSeparator);
		try {
			writer.document();
			for (int i = 0; i < writer.chunks.size(); i++) {
				output.write(writer.chunks.get(i), 0, writer.chunkSizes.get(i));
			}
			output.write(writer.out, 0, writer.size);
		} finally {
			// the chunks of one CHUNK are kept for the next save; a larger one (a long value) is not
			writer.chunks.add(writer.out);
			for (byte[] chunk : writer.chunks) {
				if (chunk.length == SpareBuffers.CHUNK) {
					writer.spare.add(chunk);
				}
			}
			SpareBuffers.giveChunks(writer.spare);
		}
	}

	private void document() throws NotOurs {
		if (model.eClass() != StatechartPackage.Literals.MODEL || ((InternalEObject) model).eIsProxy()) {
			throw new NotOurs("the root is not a plain model");
		}
		InternalEList<Node> nodes = (InternalEList<Node>) model.getNodes();
		InternalEList<Transition> transitions = (InternalEList<Transition>) model.getTransitions();
		InternalEList<Variable> variables = (InternalEList<Variable>) model.getVariables();
		for (int i = 0; i < variables.size(); i++) {
			Variable variable = variables.basicGet(i);
			plain(variable, StatechartPackage.Literals.VARIABLE);
			variablePaths.put(variable, path(null, VARIABLE_PATH, i));
		}
		append(HEADER);
		line();
		append(ROOT);
		attribute(NAME, model.getName());
		if (nodes.isEmpty() && transitions.isEmpty() && variables.isEmpty()) {
			append('/');
			append('>');
			line();
			return;
		}
		append('>');
		line();
		for (int i = 0; i < nodes.size(); i++) {
			tree(nodes.basicGet(i), i);
		}
		for (int i = 0; i < transitions.size(); i++) {
			Transition transition = transitions.basicGet(i);
			plain(transition, StatechartPackage.Literals.TRANSITION);
			indent(1);
			append('<');
			append(TRANSITIONS);
			attribute(TE, transition.getTE());
			attribute(NAME, transition.getName());
			end(SOURCE, transition.eGet(StatechartPackage.Literals.TRANSITION__SOURCE, false));
			end(TARGET, transition.eGet(StatechartPackage.Literals.TRANSITION__TARGET, false));
			append('/');
			append('>');
			line();
		}
		for (int i = 0; i < variables.size(); i++) {
			Variable variable = variables.basicGet(i);
			indent(1);
			append('<');
			append(VARIABLES);
			attribute(NAME, variable.getName());
			attribute(TYPE, variable.getType());
			append('/');
			append('>');
			line();
		}
		append(ROOT_END);
		line();
	}

	/** A top-level state and everything in it, without recursion: states nest as deep as a formula does. */
	private void tree(Node top, int index) throws NotOurs {
		Node[] open = new Node[16];
		int[] next = new int[16];
		int depth = 0;
		if (start(top, 1)) {
			open[0] = top;
			depth = 1;
		}
		while (depth > 0) {
			Node parent = open[depth - 1];
			InternalEList<Node> children = (InternalEList<Node>) parent.getChildren();
			int child = next[depth - 1];
			if (child < children.size()) {
				next[depth - 1] = child + 1;
				Node state = children.basicGet(child);
				if (start(state, depth + 1)) {
					if (depth == open.length) {
						open = Arrays.copyOf(open, depth * 2);
						next = Arrays.copyOf(next, depth * 2);
					}
					open[depth] = state;
					next[depth] = 0;
					depth++;
				}
			} else {
				next[depth - 1] = 0;
				open[depth - 1] = null;
				depth--;
				indent(depth + 1);
				append('<');
				append('/');
				append(depth == 0 ? NODES : CHILDREN);
				append('>');
				line();
			}
		}
	}

	/** {@code parent + segment + index}: the path of an element of a list; {@code parent} is null for the model's lists. */
	private static byte[] path(byte[] parent, byte[] segment, int index) {
		int digits = 1;
		for (int rest = index / 10; rest > 0; rest /= 10) {
			digits++;
		}
		int parentLength = parent == null ? 0 : parent.length;
		byte[] path = new byte[parentLength + segment.length + digits];
		if (parent != null) {
			System.arraycopy(parent, 0, path, 0, parentLength);
		}
		System.arraycopy(segment, 0, path, parentLength, segment.length);
		for (int i = path.length - 1, rest = index; i >= path.length - digits; i--, rest /= 10) {
			path[i] = (byte) ('0' + rest % 10);
		}
		return path;
	}

	/**
	 * The table of every state's path, made the first time a transition's end is not found by
	 * {@link LastPath} (a model whose transitions jump about its large lists).
	 */
	private StatePaths statePaths() {
		if (statePaths == null) {
			// a statechart has about as many states as transitions: sized so that it seldom grows
			statePaths = new StatePaths(model.getTransitions().size() + 16);
			InternalEList<Node> nodes = (InternalEList<Node>) model.getNodes();
			Node[] open = new Node[16];
			long[] paths = new long[16];
			int[] next = new int[16];
			for (int i = 0; i < nodes.size(); i++) {
				open[0] = nodes.basicGet(i);
				paths[0] = statePaths.add(open[0], 0L, NODE_PATH, i);
				next[0] = 0;
				int depth = 1;
				while (depth > 0) {
					InternalEList<Node> children = (InternalEList<Node>) open[depth - 1].getChildren();
					int child = next[depth - 1]++;
					if (child < children.size()) {
						if (depth == open.length) {
							open = Arrays.copyOf(open, depth * 2);
							paths = Arrays.copyOf(paths, depth * 2);
							next = Arrays.copyOf(next, depth * 2);
						}
						open[depth] = children.basicGet(child);
						paths[depth] = statePaths.add(open[depth], paths[depth - 1], CHILD_PATH, child);
						next[depth] = 0;
						depth++;
					} else {
						depth--;
					}
				}
			}
		}
		return statePaths;
	}

	/**
	 * A transition's end found from where it is: the states above it (through their containers)
	 * and its place in its container's list, looked for near where the last end was. Transitions
	 * mostly come in the order of their states and join neighbours, so the states above are those
	 * of the last end and the place is a few steps from its place: no table to reach, no identity
	 * hash. An end that is not near (in a large list) is left to the table, {@link #statePaths()}.
	 */
	private final class LastPath {
		/** The last end's path, and for each level (0: a state of the model) its state, its index in its list and where its path ends. */
		private byte[] path = new byte[256];
		private Object[] states = new Object[16];
		private int[] indexes = new int[16];
		private int[] ends = new int[16];
		private int levels;
		/** The states from an end up to the model, the model's state first. */
		private Object[] above = new Object[16];

		/** Writes the path of a state of the model; false when it is not found this way. */
		boolean write(Object state) {
			if (levels > 0 && state == states[levels - 1]) {
				append(path, 0, ends[levels - 1]);
				return true;
			}
			// the states above, up to one of the model
			int depth = 0;
			Object current = state;
			while (true) {
				if (!(current instanceof InternalEObject element)) {
					return false;
				}
				if (depth == above.length) {
					above = Arrays.copyOf(above, depth * 2);
				}
				above[depth++] = current;
				Object container = element.eInternalContainer();
				if (container == model) {
					break;
				}
				if (!(container instanceof Node)) {
					return false;
				}
				current = container;
			}
			// the deepest level the last path shares; the levels under it found in their lists
			int common = Math.min(depth, levels) - 1;
			while (common >= 0 && above[depth - 1 - common] != states[common]) {
				common--;
			}
			if (depth > states.length) {
				states = Arrays.copyOf(states, Math.max(depth, states.length * 2));
				indexes = Arrays.copyOf(indexes, states.length);
				ends = Arrays.copyOf(ends, states.length);
			}
			int length = common < 0 ? 0 : ends[common];
			for (int level = common + 1; level < depth; level++) {
				Object element = above[depth - 1 - level];
				java.util.List<?> list = level == 0 ? model.getNodes() : ((Node) above[depth - level]).getChildren();
				int index = indexNear(list, element, level < levels ? indexes[level] : 0);
				if (index < 0) {
					// the levels from here on are not known: the last path ends above them
					levels = level;
					return false;
				}
				length = segment(length, level == 0 ? NODE_PATH : CHILD_PATH, index);
				states[level] = element;
				indexes[level] = index;
				ends[level] = length;
			}
			levels = depth;
			append(path, 0, length);
			return true;
		}

		/** Writes {@code segment + index} into the path at {@code length}; returns the new length. */
		private int segment(int length, byte[] segment, int index) {
			int digits = 1;
			for (int rest = index / 10; rest > 0; rest /= 10) {
				digits++;
			}
			int newLength = length + segment.length + digits;
			if (newLength > path.length) {
				path = Arrays.copyOf(path, Math.max(newLength, path.length * 2));
			}
			System.arraycopy(segment, 0, path, length, segment.length);
			for (int i = newLength - 1, rest = index; i >= newLength - digits; i--, rest /= 10) {
				path[i] = (byte) ('0' + rest % 10);
			}
			return newLength;
		}
	}

	/**
	 * How many elements of lists longer than 256 may yet be compared beyond the windows of
	 * {@link #indexNear}: 16 per transition, so that a model whose transitions jump about a long
	 * list costs little more than the table would.
	 */
	private long scanBudget;

	/**
	 * Where an element is in a list, looked for from {@code hint} on and a little before it: the
	 * whole of a short list, a window of a long one, then the whole of it (of a list longer than
	 * 256 only while {@link #scanBudget} lasts), so that no model makes this quadratic; -1 when it
	 * is not found.
	 */
	private int indexNear(java.util.List<?> list, Object element, int hint) {
		if (!(list instanceof org.eclipse.emf.common.util.BasicEList<?> basic)) {
			return -1;
		}
		Object[] data = basic.data();
		int size = basic.size();
		int from;
		int to;
		if (size <= 64) {
			from = 0;
			to = size;
		} else {
			from = Math.max(0, Math.min(hint, size) - 16);
			to = Math.min(size, from + 64);
		}
		int start = Math.min(Math.max(hint, from), to);
		for (int i = start; i < to; i++) {
			if (data[i] == element) {
				return i;
			}
		}
		for (int i = from; i < start; i++) {
			if (data[i] == element) {
				return i;
			}
		}
		// a choice's transitions go from its first state to each of a hundred others and back
		if (to - from < size && (size <= 256 || scanBudget >= size)) {
			scanBudget -= size > 256 ? size : 0;
			for (int i = 0; i < size; i++) {
				if (data[i] == element) {
					return i;
				}
			}
		}
		return -1;
	}

	/**
	 * Each state's positional path, found by the state's identity: an open-addressing table of
	 * states and, for each, where its path lies in one array of all paths, which are kept in
	 * document order. A transition's ends are mostly states written near each other, so their
	 * paths are near each other too; one object per path would scatter them over the heap.
	 */
	private static final class StatePaths {
		private Node[] states;
		/** For each slot of {@link #states}, where its path is: {@code start << 32 | length}, one array to reach instead of two. */
		private long[] places;
		private int count;
		private byte[] bytes;
		private int size;

		StatePaths(int expected) {
			// paths are some 50 bytes in a formula's statechart: sized so that it seldom grows
			bytes = new byte[Math.max(1 << 12, expected * 56)];
			int capacity = Integer.highestOneBit(Math.max(16, expected * 2) - 1) << 1;
			states = new Node[capacity];
			places = new long[capacity];
		}

		/**
		 * Keeps the path {@code parent + segment + index} of a state. A path is given and returned
		 * as its place among all paths, {@code start << 32 | length}; 0 is no path.
		 */
		long add(Node state, long parent, byte[] segment, int index) {
			if (2 * (count + 1) > states.length) {
				grow();
			}
			int parentStart = (int) (parent >>> 32);
			int parentLength = (int) parent;
			int digits = 1;
			for (int rest = index / 10; rest > 0; rest /= 10) {
				digits++;
			}
			int length = parentLength + segment.length + digits;
			if (size + length > bytes.length) {
				bytes = Arrays.copyOf(bytes, Math.max(bytes.length * 2, size + length));
			}
			int start = size;
			System.arraycopy(bytes, parentStart, bytes, start, parentLength);
			System.arraycopy(segment, 0, bytes, start + parentLength, segment.length);
			for (int i = start + length - 1, rest = index; i >= start + length - digits; i--, rest /= 10) {
				bytes[i] = (byte) ('0' + rest % 10);
			}
			size += length;
			long place = (long) start << 32 | length;
			int slot = slot(state);
			states[slot] = state;
			places[slot] = place;
			count++;
			return place;
		}

		/** The slot of a state, or of the empty place where it would go. */
		private int slot(Object state) {
			int mask = states.length - 1;
			int slot = (System.identityHashCode(state) * 0x9E3779B9) >>> 7 & mask;
			while (states[slot] != null && states[slot] != state) {
				slot = (slot + 1) & mask;
			}
			return slot;
		}

		/** Writes the path of a state; false when it has none, as it is not a state of the model. */
		boolean write(Object state, StctWriter writer) {
			int slot = slot(state);
			if (states[slot] == null) {
				return false;
			}
			long place = places[slot];
			writer.append(bytes, (int) (place >>> 32), (int) place);
			return true;
		}

		private void grow() {
			Node[] oldStates = states;
			long[] oldPlaces = places;
			states = new Node[oldStates.length * 2];
			places = new long[states.length];
			for (int i = 0; i < oldStates.length; i++) {
				if (oldStates[i] != null) {
					int slot = slot(oldStates[i]);
					states[slot] = oldStates[i];
					places[slot] = oldPlaces[i];
				}
			}
		}
	}

	/** The start tag of a state at a level (1 for the model's states); returns whether it has children, and so stays open. */
	private boolean start(Node node, int level) throws NotOurs {
		plain(node, StatechartPackage.Literals.NODE);
		indent(level);
		append('<');
		append(level == 1 ? NODES : CHILDREN);
		attribute(NAME, node.getName());
		attribute(LABEL, node.getLabel());
		attribute(TYPE, node.getType());
		attribute(ACTIVITY, node.getActivity());
		InternalEList<Variable> variables = (InternalEList<Variable>) node.getVariables();
		if (!variables.isEmpty()) {
			append(STATE_VARIABLES);
			for (int i = 0; i < variables.size(); i++) {
				byte[] path = variablePaths.get(variables.basicGet(i));
				if (path == null) {
					throw new NotOurs("a state reads a variable that is not the model's");
				}
				if (i > 0) {
					append(' ');
				}
				append(path);
			}
			append('"');
		}
		if (node.getChildren().isEmpty()) {
			append('/');
			append('>');
			line();
			return false;
		}
		append('>');
		line();
		return true;
	}

	/** An element of exactly the metamodel's class, which EMF writes without type information. */
	private static void plain(EObject element, org.eclipse.emf.ecore.EClass eClass) throws NotOurs {
		if (element.eClass() != eClass || ((InternalEObject) element).eIsProxy()) {
			throw new NotOurs("an element of another class, or a proxy");
		}
	}

	/** A transition's end as the path of its state in this model, or nothing when it has none. */
	private void end(byte[] opening, Object value) throws NotOurs {
		if (value == null) {
			return;
		}
		append(opening);
		if (!lastPath.write(value) && !statePaths().write(value, this)) {
			throw new NotOurs("a transition end that is not a state of the model");
		}
		append('"');
	}

	/** {@code name="value"} with EMF's escapes, or nothing for a value that is not set. */
	@SuppressWarnings("deprecation") // String.getBytes(int, int, byte[], int): the fastest copy of ASCII text
	private void attribute(byte[] opening, String value) throws NotOurs {
		if (value == null) {
			return;
		}
		append(opening);
		int length = value.length();
		if (plain(value)) {
			// nothing to escape: the characters are their bytes
			ensure(length);
			value.getBytes(0, length, out, size);
			size += length;
			append('"');
			return;
		}
		for (int i = 0; i < length; i++) {
			char c = value.charAt(i);
			if (c >= 0x20 && c < 0x80) {
				switch (c) {
				case '&' -> append(AMP);
				case '<' -> append(LT);
				case '"' -> append(QUOT);
				default -> append((byte) c);
				}
			} else if (c == '\n') {
				append(LF);
			} else if (c == '\r') {
				append(CR);
			} else if (c == '\t') {
				append(TAB);
			} else if (c < 0x20 || c == 0xFFFE || c == 0xFFFF) {
				throw new NotOurs("a character XML 1.0 cannot hold");
			} else if (Character.isHighSurrogate(c) && i + 1 < length && Character.isLowSurrogate(value.charAt(i + 1))) {
				reference(Character.toCodePoint(c, value.charAt(++i)));
			} else if (Character.isSurrogate(c)) {
				throw new NotOurs("a lone surrogate");
			} else {
				reference(c);
			}
		}
		append('"');
	}

	/** Whether a text is printable ASCII without {@code & < "}: written as it is. */
	private static boolean plain(String value) {
		for (int i = 0, length = value.length(); i < length; i++) {
			char c = value.charAt(i);
			if (c < 0x20 || c >= 0x80 || c == '&' || c == '<' || c == '"') {
				return false;
			}
		}
		return true;
	}

	private static final byte[] AMP = ascii("&amp;");
	private static final byte[] LT = ascii("&lt;");
	private static final byte[] QUOT = ascii("&quot;");
	private static final byte[] LF = ascii("&#xA;");
	private static final byte[] CR = ascii("&#xD;");
	private static final byte[] TAB = ascii("&#x9;");

	/** {@code &#x...;} in lower-case hex, as EMF writes a character ASCII lacks. */
	private void reference(int codePoint) {
		append('&');
		append('#');
		append('x');
		int digits = Math.max(1, (35 - Integer.numberOfLeadingZeros(codePoint)) / 4);
		ensure(digits);
		for (int shift = (digits - 1) * 4; shift >= 0; shift -= 4) {
			out[size++] = HEX[(codePoint >>> shift) & 0xF];
		}
		append(';');
	}

	private void indent(int level) {
		ensure(2 * level);
		Arrays.fill(out, size, size + 2 * level, (byte) ' ');
		size += 2 * level;
	}

	private void line() {
		append(lineSeparator);
	}

	private void append(char c) {
		append((byte) c);
	}

	private void append(byte b) {
		if (size == out.length) {
			ensure(1);
		}
		out[size++] = b;
	}

	private void append(byte[] bytes) {
		append(bytes, 0, bytes.length);
	}

	private void append(byte[] bytes, int offset, int length) {
		ensure(length);
		System.arraycopy(bytes, offset, out, size, length);
		size += length;
	}

	/** Room for {@code more} bytes in one piece at the end of the current chunk. */
	private void ensure(int more) {
		if (size + more > out.length) {
			chunks.add(out);
			chunkSizes.add(size);
			out = more <= SpareBuffers.CHUNK ? SpareBuffers.chunk(spare) : new byte[more];
			size = 0;
		}
	}

	private static byte[] opening(String attribute) {
		return ascii(" " + attribute + "=\"");
	}

	private static byte[] ascii(String text) {
		return text.getBytes(java.nio.charset.StandardCharsets.US_ASCII);
	}
}
