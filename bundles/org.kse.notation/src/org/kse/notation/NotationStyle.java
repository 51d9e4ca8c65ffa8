package org.kse.notation;

import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Pattern;

import org.kse.model.NodeKind;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParseException;
import com.google.gson.JsonParser;

/**
 * The thesis notation's look: per state kind its shape, colours, stroke and corner radius, the
 * fonts of names, labels and transition expressions, and the transitions' line and arrow head.
 * It is read from {@code notation-style.json} beside this class, the one file that both
 * {@code kse diagram} (through {@link SvgDiagram}) and the diagram page (its {@code views.tsx}
 * imports the same file when it is bundled) draw from, so the two pictures cannot drift apart
 * (ADR 0020).
 */
public final class NotationStyle {

	/** The file, a resource of this package. */
	public static final String RESOURCE = "notation-style.json";

	/** What a state is drawn as; the JSON names them in camel case ({@code ringedDisc}). */
	public enum Shape {
		/** A filled disc (START). */
		DISC("disc"),
		/** A ring round a smaller filled disc (END). */
		RINGED_DISC("ringedDisc"),
		/** A circle with a letter in it (CONDITION's "C"). */
		CIRCLED_LETTER("circledLetter"),
		/** A box with round corners and the name in its middle (BASIC). */
		ROUNDED_BOX("roundedBox"),
		/** A box with the name in its header and the label at its top right (OR, AND). */
		COMPOSITE_BOX("compositeBox");

		private final String json;

		Shape(String json) {
			this.json = json;
		}

		public String json() {
			return json;
		}
	}

	/** A default size (px), for the kinds whose size does not follow their name. */
	public record Size(double width, double height) {
	}

	/**
	 * How one kind of state is drawn. A circle's radius is half the smaller side less {@code inset}
	 * (so that a thick ring stays inside the state's bounds); {@code innerDiscRatio} is the END's
	 * centre disc's radius as a part of the whole; {@code dash} an SVG dash array or null;
	 * {@code letter} the circled letter, or null; {@code size} null where the name decides.
	 */
	public record StateStyle(Shape shape, String fill, String stroke, double strokeWidth, double cornerRadius, double inset, String dash,
			double innerDiscRatio, String innerDiscFill, String letter, Size size) {

		public boolean isCircle() {
			return shape == Shape.DISC || shape == Shape.RINGED_DISC || shape == Shape.CIRCLED_LETTER;
		}
	}

	/**
	 * A text's font, colour and where it goes: for a composite's caption {@code x} from the left and
	 * {@code y} the baseline below the top; for its label {@code x} from the right and {@code y} the
	 * baseline; for a transition's expression the offset of the text from its label box's corner.
	 */
	public record TextStyle(double size, String weight, String colour, double x, double y) {

		public boolean bold() {
			return weight.equals("bold") || weight.matches("[6-9]00");
		}
	}

	/** A transition's line. */
	public record Line(String colour, double width) {
	}

	/** A transition's arrow head: a triangle {@code length} long and {@code width} wide at its base. */
	public record Arrow(double length, double width, String fill, String stroke, double strokeWidth) {
	}

	private static final Pattern COLOUR = Pattern.compile("#[0-9a-f]{6}");

	private static final NotationStyle STYLE = load();

	private final String fontFamily;
	private final Map<String, StateStyle> states;
	private final TextStyle centredCaption;
	private final TextStyle letterCaption;
	private final TextStyle headerCaption;
	private final TextStyle label;
	private final TextStyle transitionLabel;
	private final Line line;
	private final Arrow arrow;

	private NotationStyle(String fontFamily, Map<String, StateStyle> states, TextStyle centredCaption, TextStyle letterCaption,
			TextStyle headerCaption, TextStyle label, TextStyle transitionLabel, Line line, Arrow arrow) {
		this.fontFamily = fontFamily;
		this.states = states;
		this.centredCaption = centredCaption;
		this.letterCaption = letterCaption;
		this.headerCaption = headerCaption;
		this.label = label;
		this.transitionLabel = transitionLabel;
		this.line = line;
		this.arrow = arrow;
	}

	/** The notation's style, read once from the bundle. */
	public static NotationStyle get() {
		return STYLE;
	}

	private static NotationStyle load() {
		try (InputStream in = NotationStyle.class.getResourceAsStream(RESOURCE)) {
			if (in == null) {
				throw new IllegalStateException(RESOURCE + " is missing from the org.kse.notation bundle");
			}
			return read(new InputStreamReader(in, StandardCharsets.UTF_8), RESOURCE);
		} catch (IOException e) {
			throw new IllegalStateException(RESOURCE + ": " + e.getMessage(), e);
		}
	}

	/**
	 * Reads a style in the format of {@code notation-style.json}; {@code source} names it in errors.
	 * Every kind of {@link NodeKind} and {@code unknown} must have a style: a kind added to the model
	 * without one is an error here, not a state drawn in some default.
	 *
	 * @throws IllegalArgumentException what is wrong, with the file and the line and column (for
	 *                                  syntax) or the JSON path (for a missing or wrong value)
	 */
	public static NotationStyle read(Reader text, String source) {
		JsonObject root;
		try {
			JsonElement parsed = JsonParser.parseReader(text);
			if (!parsed.isJsonObject()) {
				throw new IllegalArgumentException(source + ": the style is not a JSON object");
			}
			root = parsed.getAsJsonObject();
		} catch (JsonParseException e) {
			// Gson's message ends with "at line L column C path $.x"
			throw new IllegalArgumentException(source + ": " + e.getMessage(), e);
		}
		Reading in = new Reading(source);
		Map<String, StateStyle> states = new LinkedHashMap<>();
		JsonObject kinds = in.object(root, "states", "$");
		for (String kind : kindNames()) {
			states.put(kind, state(in, in.object(kinds, kind, "$.states"), "$.states." + kind));
		}
		JsonObject captions = in.object(root, "captions", "$");
		JsonObject transitions = in.object(root, "transitions", "$");
		JsonObject line = in.object(transitions, "line", "$.transitions");
		JsonObject arrow = in.object(transitions, "arrow", "$.transitions");
		String arrowPath = "$.transitions.arrow";
		return new NotationStyle(in.string(root, "fontFamily", "$"), Collections.unmodifiableMap(states),
				text(in, captions, "$.captions", "centred", null, null), text(in, captions, "$.captions", "letter", null, null),
				text(in, captions, "$.captions", "header", "x", "baseline"), text(in, captions, "$.captions", "label", "right", "baseline"),
				text(in, transitions, "$.transitions", "label", "x", "y"),
				new Line(in.colour(line, "colour", "$.transitions.line"), in.number(line, "width", "$.transitions.line")),
				new Arrow(in.number(arrow, "length", arrowPath), in.number(arrow, "width", arrowPath), in.colour(arrow, "fill", arrowPath),
						in.colour(arrow, "stroke", arrowPath), in.number(arrow, "strokeWidth", arrowPath)));
	}

	/** The kinds the file must style: every {@link NodeKind} in lower case, and {@code unknown}. */
	public static java.util.List<String> kindNames() {
		java.util.List<String> names = new java.util.ArrayList<>();
		for (NodeKind kind : NodeKind.values()) {
			names.add(kind.name().toLowerCase(Locale.ROOT));
		}
		names.add("unknown");
		return names;
	}

	private static StateStyle state(Reading in, JsonObject style, String path) {
		String shapeName = in.string(style, "shape", path);
		Shape shape = null;
		for (Shape each : Shape.values()) {
			if (each.json().equals(shapeName)) {
				shape = each;
			}
		}
		if (shape == null) {
			throw new IllegalArgumentException(in.source + ": " + path + ".shape: \"" + shapeName + "\" is no shape (disc, ringedDisc, circledLetter, roundedBox, compositeBox)");
		}
		JsonObject inner = shape == Shape.RINGED_DISC ? in.object(style, "innerDisc", path) : null;
		JsonObject size = style.has("size") ? in.object(style, "size", path) : null;
		boolean circle = shape == Shape.DISC || shape == Shape.RINGED_DISC || shape == Shape.CIRCLED_LETTER;
		return new StateStyle(shape, in.colour(style, "fill", path), in.colour(style, "stroke", path), in.number(style, "strokeWidth", path),
				circle ? 0 : in.number(style, "cornerRadius", path), circle ? in.number(style, "inset", path) : 0,
				style.has("dash") ? in.string(style, "dash", path) : null, inner == null ? 0 : in.number(inner, "ratio", path + ".innerDisc"),
				inner == null ? null : in.colour(inner, "fill", path + ".innerDisc"),
				shape == Shape.CIRCLED_LETTER ? in.string(style, "letter", path) : null,
				size == null ? null : new Size(in.number(size, "width", path + ".size"), in.number(size, "height", path + ".size")));
	}

	private static TextStyle text(Reading in, JsonObject parent, String parentPath, String name, String x, String y) {
		JsonObject style = in.object(parent, name, parentPath);
		String path = parentPath + "." + name;
		return new TextStyle(in.number(style, "size", path), in.string(style, "weight", path), in.colour(style, "colour", path),
				x == null ? 0 : in.number(style, x, path), y == null ? 0 : in.number(style, y, path));
	}

	/** Reads values, saying which file and which JSON path lacks one. */
	private record Reading(String source) {

		JsonObject object(JsonObject parent, String name, String path) {
			JsonElement value = parent.get(name);
			if (value == null || !value.isJsonObject()) {
				throw new IllegalArgumentException(source + ": " + path + "." + name + ": " + (value == null ? "missing" : "not an object"));
			}
			return value.getAsJsonObject();
		}

		String string(JsonObject parent, String name, String path) {
			JsonElement value = parent.get(name);
			if (value == null || !value.isJsonPrimitive() || !value.getAsJsonPrimitive().isString()) {
				throw new IllegalArgumentException(source + ": " + path + "." + name + ": " + (value == null ? "missing" : "not a string"));
			}
			return value.getAsString();
		}

		double number(JsonObject parent, String name, String path) {
			JsonElement value = parent.get(name);
			if (value == null || !value.isJsonPrimitive() || !value.getAsJsonPrimitive().isNumber()) {
				throw new IllegalArgumentException(source + ": " + path + "." + name + ": " + (value == null ? "missing" : "not a number"));
			}
			return value.getAsDouble();
		}

		/** #rrggbb in lower case only: the page and the picture then write a colour alike, and a test compares them as text. */
		String colour(JsonObject parent, String name, String path) {
			String colour = string(parent, name, path);
			if (!COLOUR.matcher(colour).matches()) {
				throw new IllegalArgumentException(source + ": " + path + "." + name + ": \"" + colour + "\" is not a colour #rrggbb (lower case)");
			}
			return colour;
		}
	}

	/** The font family of every text of the diagram (DejaVu Sans first: {@link TextWidth} measures with it). */
	public String fontFamily() {
		return fontFamily;
	}

	/** How a state of this kind is drawn; {@code null} (a type the model does not know) is drawn as {@code unknown}. */
	public StateStyle of(NodeKind kind) {
		return states.get(kind == null ? "unknown" : kind.name().toLowerCase(Locale.ROOT));
	}

	/** The styles by kind name ({@code start} … {@code and}, {@code unknown}), in the file's order. */
	public Map<String, StateStyle> states() {
		return states;
	}

	/** The name in the middle of a state that holds no others (BASIC). */
	public TextStyle centredCaption() {
		return centredCaption;
	}

	/** The letter of a circled-letter state (CONDITION's "C"). */
	public TextStyle letterCaption() {
		return letterCaption;
	}

	/** The caption in a composite's header. */
	public TextStyle headerCaption() {
		return headerCaption;
	}

	/** A composite's hierarchical label at its top right. */
	public TextStyle label() {
		return label;
	}

	/** A transition's expression. */
	public TextStyle transitionLabel() {
		return transitionLabel;
	}

	public Line line() {
		return line;
	}

	public Arrow arrow() {
		return arrow;
	}
}
