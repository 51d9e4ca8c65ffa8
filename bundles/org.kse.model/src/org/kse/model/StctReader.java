package org.kse.model;

import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;

import org.eclipse.emf.common.util.EList;
import org.eclipse.emf.ecore.InternalEObject;
import org.eclipse.emf.ecore.util.InternalEList;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.StatechartFactory;
import org.kse.model.statechart.StatechartPackage;
import org.kse.model.statechart.Transition;
import org.kse.model.statechart.Variable;

/**
 * Reads the one XMI dialect that KSE and the original tool write (ADR 0026) in a single pass over
 * the bytes, building the model with the generated factory. It accepts a file only when it is sure
 * EMF's parser would read it to the same model: anything else (another encoding, a DOCTYPE, an
 * entity, a processing instruction, text, CDATA, xsi:type, an href, an ID, an element or attribute
 * it does not know, a reference that is not a plain positional path or leads nowhere or to the
 * wrong kind of element, nesting or predefined entities at the parser's limits for the load,
 * anything that is not well-formed) raises {@link NotOurs}, and the caller hands the same bytes to
 * EMF, whose messages and safety rules then apply unchanged. Nothing it builds is attached to a
 * resource until the whole file has been read and every reference resolved.
 */
final class StctReader {

	/** The input is outside the dialect; the message says where and why (for tests and tracing only). */
	static final class NotOurs extends Exception {
		private static final long serialVersionUID = 1L;

		NotOurs(String why) {
			super(why, null, false, false);
		}
	}

	/** The model, and the encoding EMF would record on the resource for this file. */
	record Result(Model model, String encoding) {
	}

	private static final String XMI_URI = "http://www.omg.org/XMI";

	// element kinds, also the index into ATTRIBUTES
	private static final int MODEL = 0;
	private static final int NODE = 1;
	private static final int TRANSITION = 2;
	private static final int VARIABLE = 3;

	/** The attributes each kind of element may have, in the order of the metamodel's features. */
	private static final String[][] ATTRIBUTES = { { "name" }, { "name", "label", "type", "activity", "variables" }, { "TE", "name", "source", "target" },
			{ "name", "type" } };

	private static final byte[][][] ATTRIBUTE_BYTES = java.util.Arrays.stream(ATTRIBUTES)
			.map(names -> java.util.Arrays.stream(names).map(name -> name.getBytes(StandardCharsets.US_ASCII)).toArray(byte[][]::new)).toArray(byte[][][]::new);

	/**
	 * For each attribute whose name and {@code =} fit in eight bytes, those bytes as a little-endian
	 * long and the mask of them (0 for the longer names); {@link #nameAndEquals} tells that
	 * {@link #attributeIndex} stepped over both.
	 */
	private static final long[][] EQUALS_WORDS = new long[ATTRIBUTES.length][];
	private static final long[][] EQUALS_MASKS = new long[ATTRIBUTES.length][];

	static {
		for (int kind = 0; kind < ATTRIBUTES.length; kind++) {
			EQUALS_WORDS[kind] = new long[ATTRIBUTES[kind].length];
			EQUALS_MASKS[kind] = new long[ATTRIBUTES[kind].length];
			for (int index = 0; index < ATTRIBUTES[kind].length; index++) {
				byte[] bytes = (ATTRIBUTES[kind][index] + "=").getBytes(StandardCharsets.US_ASCII);
				if (bytes.length <= 8) {
					long word = 0;
					for (int i = bytes.length - 1; i >= 0; i--) {
						word = word << 8 | (bytes[i] & 0xFF);
					}
					EQUALS_WORDS[kind][index] = word;
					EQUALS_MASKS[kind][index] = bytes.length == 8 ? -1L : (1L << (8 * bytes.length)) - 1;
				}
			}
		}
	}

	private boolean nameAndEquals;

	/**
	 * Eight bytes read as one long, and the constants that find a byte in them: a byte of
	 * {@code word ^ c * ONES} is zero where the byte is {@code c}, and {@code (x - ONES) & ~x & HIGHS}
	 * is not zero exactly when some byte of {@code x} is zero (likewise below 0x20 with
	 * {@code SPACES}; a byte above 0x7F has its high bit set).
	 */
	private static final java.lang.invoke.VarHandle LONGS = java.lang.invoke.MethodHandles.byteArrayViewVarHandle(long[].class,
			java.nio.ByteOrder.LITTLE_ENDIAN);
	private static final long ONES = 0x0101010101010101L;
	private static final long HIGHS = 0x8080808080808080L;
	private static final long SPACES = 0x2020202020202020L;
	private static final long AMPERSANDS = '&' * ONES;
	private static final long ANGLES = '<' * ONES;

	private static final StatechartFactory FACTORY = StatechartFactory.eINSTANCE;

	/**
	 * The JDK parser's limits as configured for this JVM (jaxp.properties, system properties), for a
	 * load whose options do not set them: the JDK counts each {@code &amp;}, {@code &lt;} and
	 * {@code &apos;} in attribute values as one character of the document's "general entity",
	 * {@code &quot;} and {@code &gt;} as two, and refuses a document past either entity size limit
	 * (100,000 in JDK 25); its default element depth is 100. KSE's own loads set all three
	 * ({@code StatechartResources.loadOptions()}); the reader follows what a load sets.
	 */
	static final class ParserLimits {
		static final int GENERAL_ENTITY_SIZE;
		static final int TOTAL_ENTITY_SIZE;
		static final int ELEMENT_DEPTH;

		static {
			int general = 100_000;
			int total = 100_000;
			int depth = 100;
			try {
				javax.xml.parsers.SAXParserFactory factory = javax.xml.parsers.SAXParserFactory.newInstance();
				factory.setNamespaceAware(true);
				javax.xml.parsers.SAXParser parser = factory.newSAXParser();
				general = limit(parser, "jdk.xml.maxGeneralEntitySizeLimit");
				total = limit(parser, "jdk.xml.totalEntitySizeLimit");
				depth = limit(parser, "jdk.xml.maxElementDepth");
			} catch (Exception | LinkageError e) {
				// not the JDK's parser, or it does not say: the JDK 25 defaults, which only make the reader leave more files to EMF
			}
			GENERAL_ENTITY_SIZE = general;
			TOTAL_ENTITY_SIZE = total;
			ELEMENT_DEPTH = depth;
		}

		private static int limit(javax.xml.parsers.SAXParser parser, String property) throws Exception {
			int value = Integer.parseInt(String.valueOf(parser.getProperty(property)).trim());
			return value <= 0 ? Integer.MAX_VALUE : value;
		}

		private ParserLimits() {
		}
	}

	/** The file's bytes: the markup of the dialect is ASCII, so only values need decoding (from UTF-8 where the file is). */
	private final byte[] text;
	private final boolean utf8;
	/** The parser's count of predefined entities so far (see {@link ParserLimits}). */
	private int entities;
	private final int end;
	private final int maxDepth;
	/** The parser's entity size limit for this load: a file that reaches it is left to the parser, which refuses it. */
	private final int maxEntities;
	private int at;

	/** The elements open at {@link #at}, innermost last, with their tag names. */
	private Object[] open = new Object[64];
	private String[] tags = new String[64];
	private int depth;

	/** References found, resolved once every element exists: owner, feature (0 source, 1 target, 2 variables), text, offset. */
	private Object[] referenceOwners = new Object[256];
	private byte[][] referenceTexts = new byte[256][];
	private int[] referenceKinds = new int[256];
	private int[] referenceStarts = new int[256];
	private int[] referenceStops = new int[256];
	private int references;

	/** The value {@link #scanValue()} found: where it is, and whether it is ASCII without references. */
	private int valueStart;
	private int valueStop;
	private boolean valuePlain;
	private boolean valueAscii;

	private StctReader(byte[] text, int length, boolean utf8, int maxDepth, int maxEntities) {
		this.text = text;
		this.end = length;
		this.utf8 = utf8;
		this.maxDepth = maxDepth;
		this.maxEntities = maxEntities;
	}

	/**
	 * @param maxDepth the XML parser's element depth limit: a file nested that deep is left to the parser, which refuses it
	 * @param maxEntities the smaller of the parser's general and total entity size limits ({@link Integer#MAX_VALUE} for
	 *            none): a file with that many predefined entities (as the parser counts them) is left to the parser
	 */
	static Result read(byte[] bytes, int length, int maxDepth, int maxEntities) throws NotOurs {
		String encoding = declaredEncoding(bytes, length);
		// Every byte is checked where it is read: markup against the dialect, values and comments
		// for characters XML 1.0 cannot hold (and, in an ASCII file, for bytes above 0x7F).
		StctReader reader = new StctReader(bytes, length, encoding.equals("UTF-8"), maxDepth, maxEntities);
		Model model = reader.document();
		reader.resolve(model);
		return new Result(model, encoding);
	}

	/**
	 * The encoding of the XML declaration, as EMF records it: ASCII or UTF-8, the only two a model
	 * file is written in; UTF-8 without a declaration or without an encoding in it.
	 */
	private static String declaredEncoding(byte[] bytes, int length) throws NotOurs {
		if (length >= 3 && (bytes[0] & 0xFF) == 0xEF) {
			throw new NotOurs("a byte order mark");
		}
		if (length < 6 || !startsWith(bytes, 0, "<?xml") || !isSpace(bytes[5])) {
			return "UTF-8";
		}
		int close = -1;
		for (int i = 5; i + 1 < length && i < 200; i++) {
			if (bytes[i] == '?' && bytes[i + 1] == '>') {
				close = i;
				break;
			}
		}
		if (close < 0) {
			throw new NotOurs("an XML declaration that does not end");
		}
		String declaration = new String(bytes, 5, close - 5, StandardCharsets.ISO_8859_1);
		java.util.regex.Matcher matcher = java.util.regex.Pattern
				.compile("[ \\t\\r\\n]+version[ \\t\\r\\n]*=[ \\t\\r\\n]*(\"1\\.0\"|'1\\.0')(?:[ \\t\\r\\n]+encoding[ \\t\\r\\n]*=[ \\t\\r\\n]*(\"[^\"]*\"|'[^']*'))?[ \\t\\r\\n]*")
				.matcher(declaration);
		if (!matcher.matches()) {
			throw new NotOurs("an XML declaration other than version 1.0 with an encoding");
		}
		String encoding = matcher.group(2) == null ? "UTF-8" : matcher.group(2).substring(1, matcher.group(2).length() - 1);
		if (!encoding.equals("ASCII") && !encoding.equals("UTF-8")) {
			throw new NotOurs("the encoding " + encoding);
		}
		return encoding;
	}

	private static boolean startsWith(byte[] bytes, int offset, String prefix) {
		if (bytes.length - offset < prefix.length()) {
			return false;
		}
		for (int i = 0; i < prefix.length(); i++) {
			if (bytes[offset + i] != prefix.charAt(i)) {
				return false;
			}
		}
		return true;
	}

	private static boolean isSpace(int c) {
		return c == ' ' || c == '\n' || c == '\t' || c == '\r';
	}

	private NotOurs notOurs(String why) {
		int line = 1;
		int column = 1;
		for (int i = 0; i < at && i < end; i++) {
			if (text[i] == '\n') {
				line++;
				column = 1;
			} else {
				column++;
			}
		}
		return new NotOurs(line + ":" + column + ": " + why);
	}

	private Model document() throws NotOurs {
		if (startsWith("<?xml") && end > 5 && isSpace(text[5])) {
			at = indexOf("?>", at) + 2;
		}
		misc();
		if (!startsWith("<statechart:Model") || !endsName(at + "<statechart:Model".length())) {
			throw notOurs("the root element is not <statechart:Model>");
		}
		at += "<statechart:Model".length();
		if (maxDepth <= 1) {
			throw notOurs("a depth limit that leaves no room for a model");
		}
		Model model = FACTORY.createModel();
		roots = (InternalEList<Node>) model.getNodes();
		boolean empty = rootAttributes(model);
		if (!empty) {
			push(model, "statechart:Model");
			content();
		}
		misc();
		if (at != end) {
			throw notOurs("something after the root element");
		}
		return model;
	}

	/** Whitespace and comments, as before and after the root element. */
	private void misc() throws NotOurs {
		while (at < end) {
			byte c = text[at];
			if (isSpace(c)) {
				at++;
			} else if (startsWith("<!--")) {
				comment();
			} else {
				return;
			}
		}
	}

	/** A comment of printable ASCII, which may not hold "--" (the XML rule the parser enforces). */
	private void comment() throws NotOurs {
		int dashes = indexOf("--", at + 4);
		if (dashes + 2 >= end || text[dashes + 2] != '>') {
			throw notOurs("a comment that holds -- or does not end");
		}
		for (int i = at + 4; i < dashes; i++) {
			byte c = text[i];
			if (c < 0x20 && !isSpace(c)) {
				at = i;
				throw notOurs("a comment with a character other than printable ASCII");
			}
		}
		at = dashes + 3;
	}

	/** The content of the open elements, until the root element's end tag. */
	private void content() throws NotOurs {
		while (depth > 0) {
			if (at >= end) {
				throw notOurs("the file ends inside <" + tags[depth - 1] + ">");
			}
			byte c = text[at];
			if (c == ' ' || isSpace(c)) {
				skipSpace();
				continue;
			}
			if (c != '<') {
				throw notOurs("text inside an element");
			}
			if (at + 1 < end && text[at + 1] == '/') {
				endTag();
			} else if (startsWith("<!--")) {
				comment();
			} else {
				element();
			}
		}
	}

	private void endTag() throws NotOurs {
		String tag = tags[depth - 1];
		at += 2;
		if (!startsWith(tag) || !endsName(at + tag.length())) {
			throw notOurs("an end tag that does not close <" + tag + ">");
		}
		at += tag.length();
		skipSpace();
		expect('>');
		if (pendingCounts[depth - 1] > 0) {
			adopt((Node) open[depth - 1], depth - 1);
		}
		open[--depth] = null;
	}

	/**
	 * The states read inside each open state, given to it at its end tag (one list made at its
	 * size, each state's container set once): a state is given its children before it has a
	 * container itself, so setting a container does not climb up to the model each time, and no
	 * list grows by copies.
	 */
	private Object[][] pending = new Object[64][];
	private int[] pendingCounts = new int[64];

	private void pend(Node child) {
		int level = depth - 1;
		Object[] states = pending[level];
		int count = pendingCounts[level];
		if (states == null) {
			states = pending[level] = new Object[16];
		} else if (count == states.length) {
			states = pending[level] = Arrays.copyOf(states, count * 2);
		}
		states[count] = child;
		pendingCounts[level] = count + 1;
	}

	/** The states read inside a state, as its children, as {@code getChildren().add} would leave them. */
	private void adopt(Node state, int level) {
		int count = pendingCounts[level];
		Object[] states = Arrays.copyOf(pending[level], count);
		pendingCounts[level] = 0;
		EList<Node> children = state.getChildren();
		if (!(children instanceof org.eclipse.emf.common.util.BasicEList<Node> list) || !children.isEmpty()) {
			for (Object child : states) {
				add(children, (Node) child);
			}
			return;
		}
		list.setData(count, states);
		InternalEObject container = (InternalEObject) state;
		for (Object child : states) {
			// what the list's inverse add does: the opposite end, Father_of, set on the child
			org.eclipse.emf.common.notify.NotificationChain notifications = ((InternalEObject) child).eBasicSetContainer(container,
					StatechartPackage.NODE__FATHER_OF, null);
			if (notifications != null) {
				notifications.dispatch();
			}
		}
	}

	/** A child element of the innermost open element: the kinds of element each kind may contain. */
	private void element() throws NotOurs {
		Object parent = open[depth - 1];
		if (depth + 1 >= maxDepth) {
			throw notOurs("elements nested as deep as the parser's limit");
		}
		at++;
		if (parent instanceof Node node) {
			if (!name("Children")) {
				throw notOurs("an element a state does not hold");
			}
			Node child = FACTORY.createNode();
			pend(child);
			children(child, NODE, "Children");
		} else if (parent instanceof Model model) {
			if (name("nodes")) {
				Node child = FACTORY.createNode();
				add(model.getNodes(), child);
				children(child, NODE, "nodes");
			} else if (name("transitions")) {
				Transition child = FACTORY.createTransition();
				add(model.getTransitions(), child);
				children(child, TRANSITION, "transitions");
			} else if (name("variables")) {
				Variable child = FACTORY.createVariable();
				add(model.getVariables(), child);
				children(child, VARIABLE, "variables");
			} else {
				throw notOurs("an element a model does not hold");
			}
		} else {
			throw notOurs("an element inside a transition or a variable");
		}
	}

	/** A new element cannot be in its list yet: added without the list's search for it. */
	@SuppressWarnings("unchecked")
	private static <T> void add(EList<T> list, T element) {
		((InternalEList<T>) list).addUnique(element);
	}

	/** The attributes of a new element, and the element opened when it has content. */
	private void children(Object element, int kind, String tag) throws NotOurs {
		if (!attributes(element, kind)) {
			push(element, tag);
		}
	}

	private void push(Object element, String tag) {
		if (depth == open.length) {
			open = java.util.Arrays.copyOf(open, depth * 2);
			tags = java.util.Arrays.copyOf(tags, depth * 2);
		}
		if (depth == pending.length) {
			pending = java.util.Arrays.copyOf(pending, depth * 2);
			pendingCounts = java.util.Arrays.copyOf(pendingCounts, depth * 2);
		}
		open[depth] = element;
		tags[depth] = tag;
		pendingCounts[depth] = 0;
		depth++;
	}

	/** Whether the name at {@link #at} is exactly {@code name}; if so, steps over it. */
	private boolean name(String name) {
		if (startsWith(name) && endsName(at + name.length())) {
			at += name.length();
			return true;
		}
		return false;
	}

	/** Whether a name ends at {@code index}: what follows may not continue it. */
	private boolean endsName(int index) {
		if (index >= end) {
			return true;
		}
		byte c = text[index];
		return isSpace(c) || c == '/' || c == '>';
	}

	/**
	 * The attributes of the root element: the two namespaces, xmi:version 2.0 and the name. Returns
	 * whether the element is empty.
	 */
	private boolean rootAttributes(Model model) throws NotOurs {
		String xmi = null;
		String statechart = null;
		String version = null;
		String name = null;
		while (true) {
			boolean spaced = skipSpace();
			if (tagEnds()) {
				break;
			}
			if (!spaced) {
				throw notOurs("attributes without space between them");
			}
			int nameStart = at;
			String attribute = attributeName();
			String value = attributeValue();
			switch (attribute) {
			case "xmlns:xmi" -> xmi = once(xmi, value, nameStart);
			case "xmlns:statechart" -> statechart = once(statechart, value, nameStart);
			case "xmi:version" -> version = once(version, value, nameStart);
			case "name" -> name = once(name, value, nameStart);
			default -> throw notOurs("the attribute " + attribute + " on the root element");
			}
		}
		if (!XMI_URI.equals(xmi) || !StatechartPackage.eNS_URI.equals(statechart) || (version != null && !version.equals("2.0"))) {
			throw notOurs("namespaces or an XMI version other than KSE's");
		}
		if (name != null) {
			model.setName(name);
		}
		return text[at - 2] == '/';
	}

	private String once(String before, String value, int nameStart) throws NotOurs {
		if (before != null) {
			at = nameStart;
			throw notOurs("an attribute given twice");
		}
		return value;
	}

	/**
	 * The attributes of a state, a transition or a variable, set on it; references are kept for
	 * later. Returns whether the element is empty.
	 */
	private boolean attributes(Object element, int kind) throws NotOurs {
		String[] names = ATTRIBUTES[kind];
		int seen = 0;
		while (true) {
			boolean spaced = skipSpace();
			if (tagEnds()) {
				return text[at - 2] == '/';
			}
			if (!spaced) {
				throw notOurs("attributes without space between them");
			}
			int index = attributeIndex(kind);
			if (index < 0) {
				throw notOurs("an attribute KSE does not write");
			}
			if ((seen & (1 << index)) != 0) {
				throw notOurs("an attribute given twice");
			}
			seen |= 1 << index;
			if (!nameAndEquals) {
				at += names[index].length();
				skipSpace();
				expect('=');
			}
			if (at < end && text[at] != '"') {
				skipSpace();
			}
			set(element, kind, index);
		}
	}

	/** Sets the attribute {@code ATTRIBUTES[kind][index]} from the value at {@link #at}. */
	/** The index in {@code ATTRIBUTES[kind]} of the attribute name at {@link #at}, or -1: told apart by the first letter. */
	private int attributeIndex(int kind) {
		byte first = text[at];
		int index = switch (kind) {
		case NODE -> first == 'n' ? 0 : first == 'l' ? 1 : first == 't' ? 2 : first == 'a' ? 3 : first == 'v' ? 4 : -1;
		case TRANSITION -> first == 'T' ? 0 : first == 'n' ? 1 : first == 's' ? 2 : first == 't' ? 3 : -1;
		default -> first == 'n' ? 0 : first == 't' ? 1 : -1;
		};
		if (index < 0) {
			return -1;
		}
		// as KSE writes it, name="...: the name and the = in one comparison of eight bytes
		long mask = EQUALS_MASKS[kind][index];
		if (mask != 0 && at + 8 <= end && ((long) LONGS.get(text, at) & mask) == EQUALS_WORDS[kind][index]) {
			at += ATTRIBUTE_BYTES[kind][index].length + 1;
			nameAndEquals = true;
			return index;
		}
		nameAndEquals = false;
		byte[] name = ATTRIBUTE_BYTES[kind][index];
		return at + name.length <= end && Arrays.equals(text, at, at + name.length, name, 0, name.length) && attributeNameEnds(at + name.length) ? index : -1;
	}

	private void set(Object element, int kind, int index) throws NotOurs {
		switch (kind) {
		case NODE -> {
			Node node = (Node) element;
			switch (index) {
			case 0 -> node.setName(attributeValue());
			case 1 -> node.setLabel(attributeValue());
			case 2 -> node.setType(kindValue());
			case 3 -> node.setActivity(attributeValue());
			default -> reference(node, 2);
			}
		}
		case TRANSITION -> {
			Transition transition = (Transition) element;
			switch (index) {
			case 0 -> transition.setTE(attributeValue());
			case 1 -> transition.setName(attributeValue());
			default -> transitionEnd(transition, index - 2);
			}
		}
		default -> {
			Variable variable = (Variable) element;
			if (index == 0) {
				variable.setName(attributeValue());
			} else {
				variable.setType(kindValue());
			}
		}
		}
	}

	/** The model's states, to resolve a transition's ends as soon as they are read. */
	private InternalEList<Node> roots;

	/**
	 * A transition's end: resolved where it is read when it is a plain path to a state already
	 * read (lists only grow while reading, so the path leads to the same state at the end of the
	 * file), kept for the end otherwise. One pass over the path's bytes instead of a scan, a copy
	 * and a second parse.
	 */
	private void transitionEnd(Transition transition, int kind) throws NotOurs {
		int start = at;
		Node node = stateAt();
		if (node == null) {
			at = start;
			reference(transition, kind);
		} else if (kind == 0) {
			transition.setSource(node);
		} else {
			transition.setTarget(node);
		}
	}

	/**
	 * The state of the quoted path {@code //@nodes.N(/@Children.M)*} at {@link #at}, stepping over
	 * it; null, with {@link #at} anywhere, when the value is anything else or leads to no state read
	 * so far: {@link #reference} then reads it the general way.
	 */
	private Node stateAt() {
		int i = at;
		if (i + 1 + NODE_PATH.length >= end) {
			return null;
		}
		byte quote = text[i++];
		if ((quote != '"' && quote != '\'') || (long) LONGS.get(text, i) != NODE_PATH_WORD || text[i + 8] != '.') {
			return null;
		}
		i += NODE_PATH.length;
		int index = digits(i);
		if (index < 0 || index >= roots.size()) {
			return null;
		}
		i = digitsEnd;
		Node node = roots.basicGet(index);
		while (i < end) {
			byte c = text[i];
			if (c == quote) {
				at = i + 1;
				return node;
			}
			if (i + CHILD_PATH.length >= end || (long) LONGS.get(text, i) != CHILD_PATH_WORD || text[i + 8] != 'e' || text[i + 9] != 'n' || text[i + 10] != '.') {
				return null;
			}
			i += CHILD_PATH.length;
			index = digits(i);
			if (index < 0) {
				return null;
			}
			InternalEList<Node> children = (InternalEList<Node>) node.getChildren();
			if (index >= children.size()) {
				return null;
			}
			i = digitsEnd;
			node = children.basicGet(index);
		}
		return null;
	}

	private static final long NODE_PATH_WORD = (long) LONGS.get("//@nodes.".getBytes(StandardCharsets.US_ASCII), 0);
	// "/@Childr", followed by "en."
	private static final long CHILD_PATH_WORD = (long) LONGS.get("/@Children.".getBytes(StandardCharsets.US_ASCII), 0);

	/** Where the digits {@link #digits} last read end. */
	private int digitsEnd;

	/**
	 * The index written at {@code i} as KSE writes it (1 to 9 decimal digits, no leading zero),
	 * or -1; {@link #digitsEnd} is set to where it ends.
	 */
	private int digits(int i) {
		int start = i;
		int value = 0;
		while (i < end && i - start < 10) {
			int digit = text[i] - '0';
			if (digit < 0 || digit > 9) {
				break;
			}
			value = value * 10 + digit;
			i++;
		}
		int length = i - start;
		if (length < 1 || length > 9 || (length > 1 && text[start] == '0')) {
			return -1;
		}
		digitsEnd = i;
		return value;
	}

	/**
	 * A reference attribute's value, kept to be resolved at the end: as the bytes of the file
	 * where it is plain ASCII (nearly always), else as its text, which must be ASCII to be a path.
	 */
	private void reference(Object owner, int kind) throws NotOurs {
		scanValue();
		byte[] source = text;
		int start = valueStart;
		int stop = valueStop;
		if (!valuePlain || !valueAscii) {
			String value = valueText();
			for (int i = 0; i < value.length(); i++) {
				if (value.charAt(i) >= 0x80) {
					at = valueStart;
					throw notOurs("a reference that is not a path");
				}
			}
			source = value.getBytes(StandardCharsets.ISO_8859_1);
			start = 0;
			stop = source.length;
		}
		if (references == referenceOwners.length) {
			referenceOwners = Arrays.copyOf(referenceOwners, references * 2);
			referenceTexts = Arrays.copyOf(referenceTexts, references * 2);
			referenceKinds = Arrays.copyOf(referenceKinds, references * 2);
			referenceStarts = Arrays.copyOf(referenceStarts, references * 2);
			referenceStops = Arrays.copyOf(referenceStops, references * 2);
		}
		referenceOwners[references] = owner;
		referenceKinds[references] = kind;
		referenceTexts[references] = source;
		referenceStarts[references] = start;
		referenceStops[references] = stop;
		references++;
	}

	/** The end of a start tag: {@code >} or {@code />}, stepped over. */
	private boolean tagEnds() throws NotOurs {
		if (at >= end) {
			throw notOurs("the file ends inside a tag");
		}
		if (text[at] == '>') {
			at++;
			return true;
		}
		if (text[at] == '/') {
			at++;
			expect('>');
			return true;
		}
		return false;
	}

	private boolean attributeNameEnds(int index) {
		if (index >= end) {
			return true;
		}
		byte c = text[index];
		return isSpace(c) || c == '=';
	}

	/** A name of the root element's attributes, and the {@code =} after it. */
	private String attributeName() throws NotOurs {
		int start = at;
		while (at < end && !isSpace(text[at]) && text[at] != '=' && text[at] != '>' && text[at] != '/' && text[at] != '<') {
			at++;
		}
		String name = new String(text, start, at - start, StandardCharsets.ISO_8859_1);
		skipSpace();
		expect('=');
		skipSpace();
		return name;
	}

	/**
	 * A quoted value with its references to characters and the five predefined entities replaced.
	 * A literal tab or line break (which the parser turns into a space), a control character, a
	 * byte above 0x7F in an ASCII file and anything else the parser would treat otherwise are not
	 * KSE's.
	 */
	private String attributeValue() throws NotOurs {
		scanValue();
		return valueText();
	}

	/** The text of the value {@link #scanValue()} found. */
	private String valueText() throws NotOurs {
		if (valuePlain && valueAscii) {
			return asciiText();
		}
		String raw = valueAscii ? new String(text, valueStart, valueStop - valueStart, StandardCharsets.ISO_8859_1) : utf8(valueStart, valueStop);
		return valuePlain ? raw : references(raw, valueStart);
	}

	/**
	 * A plain ASCII value as text; the same text as the value before it is the same string. A
	 * state's name and label are often the same ({@code name="0.2.1" label="0.2.1"}): one string
	 * fewer to make and to keep. Strings cannot change, so sharing one is not seen.
	 */
	private String asciiText() {
		int length = valueStop - valueStart;
		if (length == lastValueStop - lastValueStart && Arrays.equals(text, valueStart, valueStop, text, lastValueStart, lastValueStop)) {
			return lastValue;
		}
		lastValue = new String(text, valueStart, length, StandardCharsets.ISO_8859_1);
		lastValueStart = valueStart;
		lastValueStop = valueStop;
		return lastValue;
	}

	/** The plain ASCII value last made into a string, and where it is. */
	private String lastValue;
	private int lastValueStart;
	private int lastValueStop = -1;

	/** The kinds ({@code type}) read so far, as the strings made for them: a model has a handful, each on thousands of states. */
	private String[] kinds = new String[8];
	private int kindCount;

	/** A state's or a variable's type: one string for each kind in the file, where it is plain ASCII. */
	private String kindValue() throws NotOurs {
		scanValue();
		if (!valuePlain || !valueAscii) {
			return valueText();
		}
		int length = valueStop - valueStart;
		for (int i = 0; i < kindCount; i++) {
			String kind = kinds[i];
			if (kind.length() == length && startsWith(text, valueStart, kind)) {
				return kind;
			}
		}
		String kind = new String(text, valueStart, length, StandardCharsets.ISO_8859_1);
		if (kindCount < kinds.length) {
			kinds[kindCount++] = kind;
		}
		return kind;
	}

	/** Finds the quoted value at {@link #at} and steps over it. */
	private void scanValue() throws NotOurs {
		if (at >= end || (text[at] != '"' && text[at] != '\'')) {
			throw notOurs("an attribute without a quoted value");
		}
		byte quote = text[at++];
		long quotes = (quote & 0xFF) * ONES;
		int start = at;
		boolean plain = true;
		boolean ascii = true;
		while (true) {
			// eight bytes at a time past those that need no more than copying
			while (at + 8 <= end) {
				long word = (long) LONGS.get(text, at);
				long quoted = word ^ quotes;
				long ampersands = word ^ AMPERSANDS;
				long angles = word ^ ANGLES;
				long special = ((quoted - ONES) & ~quoted) | ((ampersands - ONES) & ~ampersands) | ((angles - ONES) & ~angles) | ((word - SPACES) & ~word) | word;
				if ((special & HIGHS) != 0) {
					// the lowest byte marked is the first special one (a borrow only runs upwards)
					at += Long.numberOfTrailingZeros(special & HIGHS) >>> 3;
					break;
				}
				at += 8;
			}
			if (at >= end) {
				throw notOurs("a value that does not end");
			}
			byte c = text[at];
			if (c == quote) {
				break;
			}
			if (c < 0x20) {
				// negative: a byte above 0x7F
				if (c >= 0 || !utf8) {
					throw notOurs(c >= 0 ? "a control character, tab or line break in a value" : "a byte above 0x7F in an ASCII file");
				}
				ascii = false;
			} else if (c == '&') {
				plain = false;
			} else if (c == '<') {
				throw notOurs("a < in a value");
			}
			at++;
		}
		valueStart = start;
		valueStop = at++;
		valuePlain = plain;
		valueAscii = ascii;
	}

	/** Bytes of a UTF-8 file as text, when they are UTF-8 and characters XML 1.0 can hold. */
	private String utf8(int start, int stop) throws NotOurs {
		String value;
		try {
			value = StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT).onUnmappableCharacter(CodingErrorAction.REPORT)
					.decode(ByteBuffer.wrap(text, start, stop - start)).toString();
		} catch (CharacterCodingException e) {
			at = start;
			throw notOurs("a value that is not UTF-8");
		}
		if (value.indexOf('\uFFFE') >= 0 || value.indexOf('\uFFFF') >= 0) {
			at = start;
			throw notOurs("a value with a character XML 1.0 cannot hold");
		}
		return value;
	}

	/** A value's references replaced, counted as the parser counts them. */
	private String references(String raw, int offset) throws NotOurs {
		StringBuilder value = new StringBuilder(raw.length());
		int stop = raw.length();
		for (int i = 0; i < stop;) {
			char c = raw.charAt(i);
			if (c != '&') {
				value.append(c);
				i++;
				continue;
			}
			int semicolon = raw.indexOf(';', i + 1);
			if (semicolon < 0 || semicolon - i > 12) {
				at = offset;
				throw notOurs("an & that does not begin a reference");
			}
			String reference = raw.substring(i + 1, semicolon);
			switch (reference) {
			case "amp" -> value.append('&');
			case "lt" -> value.append('<');
			case "gt" -> value.append('>');
			case "quot" -> value.append('"');
			case "apos" -> value.append('\'');
			default -> value.appendCodePoint(characterReference(reference, offset));
			}
			if (reference.charAt(0) != '#') {
				entities += reference.equals("quot") || reference.equals("gt") ? 2 : 1;
				if (entities >= maxEntities) {
					at = offset;
					throw notOurs("more predefined entities than the parser reads");
				}
			}
			i = semicolon + 1;
		}
		return value.toString();
	}

	/** The character of {@code #65} or {@code #x41}; one XML 1.0 cannot hold is the parser's to refuse. */
	private int characterReference(String reference, int offset) throws NotOurs {
		int codePoint = -1;
		if (reference.length() > 2 && reference.charAt(0) == '#' && reference.charAt(1) == 'x') {
			codePoint = number(reference, 2, 16);
		} else if (reference.length() > 1 && reference.charAt(0) == '#') {
			codePoint = number(reference, 1, 10);
		}
		boolean allowed = codePoint == '\t' || codePoint == '\n' || codePoint == '\r' || (codePoint >= 0x20 && codePoint <= 0xD7FF)
				|| (codePoint >= 0xE000 && codePoint <= 0xFFFD) || (codePoint >= 0x10000 && codePoint <= 0x10FFFF);
		if (!allowed) {
			at = offset;
			throw notOurs("the reference &" + reference + "; is not a character XML can hold");
		}
		return codePoint;
	}

	/** The digits of {@code text} from {@code start} in a radix, or -1 when there are none, others or too many. */
	private static int number(String text, int start, int radix) {
		if (text.length() - start > 8) {
			return -1;
		}
		int value = 0;
		for (int i = start; i < text.length(); i++) {
			int digit = Character.digit(text.charAt(i), radix);
			// Character.digit also takes non-ASCII digits, which XML does not
			if (digit < 0 || text.charAt(i) > 'f') {
				return -1;
			}
			value = value * radix + digit;
		}
		return value;
	}

	/**
	 * Sets every reference kept while reading. Only the paths KSE writes are read here:
	 * {@code //@nodes.N(/@Children.M)*} for a state, {@code //@variables.N} for a variable, one
	 * per attribute for a transition's ends and a list separated by single spaces for a state's
	 * variables. Anything else, and any path that leads nowhere, is EMF's to read or report.
	 */
	private void resolve(Model model) throws NotOurs {
		InternalEList<Node> roots = (InternalEList<Node>) model.getNodes();
		InternalEList<Variable> modelVariables = (InternalEList<Variable>) model.getVariables();
		for (int r = 0; r < references; r++) {
			byte[] path = referenceTexts[r];
			int start = referenceStarts[r];
			int stop = referenceStops[r];
			int kind = referenceKinds[r];
			at = start;
			if (kind == 2) {
				Node node = (Node) referenceOwners[r];
				InternalEList<Variable> variables = (InternalEList<Variable>) node.getVariables();
				while (true) {
					int space = start;
					while (space < stop && path[space] != ' ') {
						space++;
					}
					Variable variable = modelVariables.basicGet(index(path, prefixed(path, start, space, VARIABLE_PATH), space, modelVariables.size()));
					// the list is unique: a variable named twice is EMF's to settle
					for (int i = 0; i < variables.size(); i++) {
						if (variables.basicGet(i) == variable) {
							throw notOurs("a variable named twice");
						}
					}
					variables.addUnique(variable);
					if (space == stop) {
						break;
					}
					start = space + 1;
				}
			} else {
				Transition transition = (Transition) referenceOwners[r];
				Node node = state(roots, path, start, stop);
				if (kind == 0) {
					transition.setSource(node);
				} else {
					transition.setTarget(node);
				}
			}
		}
	}

	private static final byte[] VARIABLE_PATH = "//@variables.".getBytes(StandardCharsets.US_ASCII);
	private static final byte[] NODE_PATH = "//@nodes.".getBytes(StandardCharsets.US_ASCII);
	private static final byte[] CHILD_PATH = "/@Children.".getBytes(StandardCharsets.US_ASCII);

	/**
	 * The path last resolved, and the state of each of its levels with where that level's index
	 * ends: transitions come in the order of their states, so the next path mostly shares all but
	 * its last levels with this one, and is resolved from there instead of from the root.
	 */
	private byte[] lastPath;
	private int lastStart;
	private int lastStop;
	private Node[] levelStates = new Node[16];
	private int[] levelEnds = new int[16];
	private int levels;

	/** The state at {@code //@nodes.N(/@Children.M)*}. */
	private Node state(InternalEList<Node> roots, byte[] path, int start, int stop) throws NotOurs {
		int length = stop - start;
		int level = -1;
		if (lastPath != null) {
			int common = Arrays.mismatch(lastPath, lastStart, lastStop, path, start, stop);
			if (common < 0) {
				common = length;
			}
			for (level = levels - 1; level >= 0; level--) {
				int end = levelEnds[level];
				if (end <= common && (end == length || path[start + end] == '/')) {
					break;
				}
			}
		}
		Node node;
		int segment;
		if (level >= 0) {
			node = levelStates[level];
			segment = start + levelEnds[level];
		} else {
			int digits = prefixed(path, start, stop, NODE_PATH);
			segment = digits;
			while (segment < stop && path[segment] != '/') {
				segment++;
			}
			node = roots.basicGet(index(path, digits, segment, roots.size()));
			level = 0;
			levelStates[0] = node;
			levelEnds[0] = segment - start;
		}
		while (segment < stop) {
			int digits = prefixed(path, segment, stop, CHILD_PATH);
			segment = digits;
			while (segment < stop && path[segment] != '/') {
				segment++;
			}
			InternalEList<Node> children = (InternalEList<Node>) node.getChildren();
			node = children.basicGet(index(path, digits, segment, children.size()));
			level++;
			if (level == levelStates.length) {
				levelStates = Arrays.copyOf(levelStates, level * 2);
				levelEnds = Arrays.copyOf(levelEnds, level * 2);
			}
			levelStates[level] = node;
			levelEnds[level] = segment - start;
		}
		levels = level + 1;
		lastPath = path;
		lastStart = start;
		lastStop = stop;
		return node;
	}

	/** Where the index begins, after {@code prefix} at {@code start}. */
	private int prefixed(byte[] path, int start, int stop, byte[] prefix) throws NotOurs {
		if (stop - start < prefix.length || !Arrays.equals(path, start, start + prefix.length, prefix, 0, prefix.length)) {
			throw notOurs("a reference that is not a path KSE writes");
		}
		return start + prefix.length;
	}

	/** A list index as KSE writes it (decimal digits, no sign, no leading zero) that is inside a list of {@code size}. */
	private int index(byte[] path, int start, int stop, int size) throws NotOurs {
		int length = stop - start;
		if (length < 1 || length > 9 || (length > 1 && path[start] == '0')) {
			throw notOurs("a reference with an index KSE does not write");
		}
		int value = 0;
		for (int i = start; i < stop; i++) {
			byte c = path[i];
			if (c < '0' || c > '9') {
				throw notOurs("a reference with an index KSE does not write");
			}
			value = value * 10 + (c - '0');
		}
		if (value >= size) {
			throw notOurs("a reference to an element that does not exist");
		}
		return value;
	}

	private boolean startsWith(String prefix) {
		int length = prefix.length();
		if (end - at < length) {
			return false;
		}
		for (int i = 0; i < length; i++) {
			if (text[at + i] != prefix.charAt(i)) {
				return false;
			}
		}
		return true;
	}

	/** Where a two-character text first occurs from {@code from}. */
	private int indexOf(String what, int from) throws NotOurs {
		char first = what.charAt(0);
		char second = what.charAt(1);
		for (int i = from; i + 1 < end; i++) {
			if (text[i] == first && text[i + 1] == second) {
				return i;
			}
		}
		at = from;
		throw notOurs("no " + what + " to end what began");
	}

	private boolean skipSpace() {
		int start = at;
		while (at + 8 <= end && (long) LONGS.get(text, at) == SPACES) {
			at += 8;
		}
		while (at < end) {
			byte c = text[at];
			// indentation first: most of a model file's whitespace
			if (c == ' ' || c == '\n' || c == '\t' || c == '\r') {
				at++;
			} else {
				break;
			}
		}
		return at > start;
	}

	private void expect(char c) throws NotOurs {
		if (at >= end || text[at] != c) {
			throw notOurs("expected " + c);
		}
		at++;
	}
}
