package org.kse.diagram.server.tests;

import java.math.BigDecimal;
import java.math.BigInteger;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.function.Supplier;

import org.kse.testing.ByteMutator;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonNull;
import com.google.gson.JsonObject;
import com.google.gson.JsonPrimitive;

/**
 * Hostile JSON-RPC messages for the diagram server, made from the messages a GLSP client really
 * sends (initialize, initializeClientSession, requestModel, the edits, save, popups, undo and
 * redo, copy and paste), with the ids of the diagram the server drew: values replaced by other
 * types, huge or negative numbers, very long or control-character strings, deep nesting, paths
 * and URIs that leave the served folder or reach the network; keys removed or added; the text
 * itself flipped, cut, truncated or repeated; sometimes noise. Everything depends on the
 * {@link Random}, so a seed replays a run.
 */
final class DiagramMessages {

	static final String SESSION = "fuzz";
	static final String DIAGRAM_TYPE = "kse-statechart";
	static final List<String> CLIENT_ACTIONS = List.of("setModel", "requestBounds", "updateModel", "message", "status", "setDirtyState", "setMarkers",
			"setClipboardData", "setPopupModel", "setEditValidationResult", "setTypeHints", "setContextActions", "setNavigationTargets", "deleteMarkers",
			"startProgress", "updateProgress", "endProgress", "rejectRequest");

	private static final List<String> STATE_TYPES = List.of("state:basic", "state:or", "state:and", "state:start", "state:end", "state:condition",
			"state:unknown", "transition", "graph", "label:name", "node", "");
	private static final List<String> KINDS = List.of("requestModel", "changeBounds", "createNode", "createEdge", "applyLabelEdit", "saveModel",
			"requestPopupModel", "glspUndo", "glspRedo", "deleteElement", "changeContainer", "requestClipboardData", "paste", "cut", "computedBounds",
			"requestEditValidation", "requestMarkers", "changeRoutingPoints", "reconnectEdge", "layout", "compound", "requestContextActions",
			"requestNavigationTargets", "requestTypeHints", "setEditMode", "externalChange", "internal.join", "requestBounds", "setModel", "updateModel",
			"message", "noSuchKind", "");
	private static final List<String> METHODS = List.of("initialize", "initializeClientSession", "disposeClientSession", "process", "shutdown", "exit",
			"$/cancelRequest", "$/setTrace", "rpc.discover", "noSuchMethod", "");

	private final Random random;
	private final ByteMutator bytes;
	private final List<String> uris;
	/** The ids of the diagram's elements, as the server last drew them. */
	private final List<String> ids = new ArrayList<>(List.of("statechart", "//@nodes.0", "//@nodes.0/@Children.0", "//@transitions.0"));
	/** Keys of copies the server handed out (requestClipboardData), for paste. */
	private final List<String> clipboardKeys = new ArrayList<>(List.of("00000000-0000-0000-0000-000000000000"));
	private int nextId = 1000;

	/**
	 * @param served the folder the server serves, {@code outside} a model beside it it must never
	 *        open or write, {@code remote} an address that must never be reached
	 */
	DiagramMessages(Random random, Path served, Path outside, String remote) {
		this.random = random;
		this.bytes = new ByteMutator(random, WORDS);
		String out = outside.toString();
		uris = List.of("Goalie.stct", "Goalie.stct", "sub/Attacker.stct", "../outside/Outside.stct", "../../../../../../etc/passwd", "/etc/passwd", out,
				"file://" + out, "file:" + out, "file:///etc/passwd", "file://localhost" + out, "file:///", "file://", "file:", "file:Goalie.stct",
				"file://" + served.resolve("Goalie.stct"), served.resolve("../outside/Outside.stct").toString(), remote + "/x.stct", remote + "/Goalie.stct",
				"https://kse-fuzz.invalid/x.stct", "ftp://127.0.0.1/x.stct", "jar:file:" + out + "!/x.stct", "platform:/resource/x/x.stct",
				"platform:/plugin/kse/model/statechart.ecore", "Goalie.stct\u0000", "Goalie.stct\u0000.txt", "sub/../../outside/Outside.stct",
				"%2e%2e/outside/Outside.stct", "..%2Foutside%2FOutside.stct", "..\\outside\\Outside.stct", "~/x.stct", "//127.0.0.1/share/x.stct",
				"\\\\127.0.0.1\\share\\x.stct", "Goalie.stct/", "", " ", ".", "..", "/", "link.stct", "linkdir/Outside.stct", "linkdir/New.stct", "New.stct",
				"folder.stct", "Goalie.notation.json", "x".repeat(5000) + ".stct", "nul.stct", "COM1.stct", "file://[::1", "file:// bad uri", "file:%00",
				"\ud83e\udd16.stct", "\u001b[2J.stct", "Goalie.STCT", "./Goalie.stct", "sub/./../Goalie.stct", served.toString());
	}

	/** What the server sent that names ids or copies, kept until the next message is made (on the test's thread). */
	private final java.util.Queue<String> heard = new java.util.concurrent.ConcurrentLinkedQueue<>();

	/** Keeps a graph or a copy the server sent (on the client's thread), to learn from before the next message. */
	void hear(String received) {
		if (received.contains("\"//@") || received.contains("application/x-kse-states")) {
			heard.add(received);
		}
	}

	/** Learns the ids of the graph and the keys of copies in what the server sent. */
	private void learn(String received) {
		var ids = java.util.regex.Pattern.compile("\"id\":\"((//@|statechart)[^\"]{0,200})\"").matcher(received);
		List<String> found = new ArrayList<>();
		while (ids.find()) {
			found.add(ids.group(1));
		}
		if (found.size() > 3) {
			this.ids.clear();
			this.ids.addAll(found);
		}
		var key = java.util.regex.Pattern.compile("\"application/x-kse-states\":\"([^\"]+)\"").matcher(received);
		while (key.find()) {
			clipboardKeys.add(key.group(1));
		}
	}

	/** One hostile message: mostly a mutation of a real one, sometimes a real one, sometimes not JSON at all. */
	String next() {
		for (String received; (received = heard.poll()) != null;) {
			learn(received);
		}
		return escapeLoneSurrogates(message());
	}

	/**
	 * A lone surrogate cannot travel in a WebSocket text frame (the client refuses to encode it);
	 * inside a JSON string it can, escaped, and reaches the server as the character.
	 */
	private static String escapeLoneSurrogates(String text) {
		StringBuilder out = new StringBuilder(text.length());
		for (int i = 0; i < text.length(); i++) {
			char c = text.charAt(i);
			boolean paired = Character.isHighSurrogate(c) && i + 1 < text.length() && Character.isLowSurrogate(text.charAt(i + 1));
			if (paired) {
				out.append(c).append(text.charAt(++i));
			} else if (Character.isSurrogate(c)) {
				out.append(String.format("\\u%04x", (int) c));
			} else {
				out.append(c);
			}
		}
		return out.toString();
	}

	private String message() {
		int mode = random.nextInt(100);
		if (mode < 12) {
			return real().toString(); // well-formed edits and saves, so later messages meet a changed model and file
		}
		if (mode < 60) {
			JsonObject message = real();
			for (int steps = 1 + random.nextInt(3); steps > 0; steps--) {
				mutate(message);
			}
			return message.toString();
		}
		if (mode < 88) {
			return text(real().toString());
		}
		return special();
	}

	// --- the messages a GLSP client sends ---

	private JsonObject real() {
		int pick = random.nextInt(100);
		if (pick < 4) {
			return request("initialize", object("applicationId", "kse-fuzz", "protocolVersion", "1.0.0", "args", new JsonObject()));
		}
		if (pick < 8) {
			return request("initializeClientSession", object("clientSessionId", SESSION, "diagramType", DIAGRAM_TYPE, "clientActionKinds",
					strings(CLIENT_ACTIONS), "args", new JsonObject()));
		}
		if (pick < 9) {
			return request("disposeClientSession", object("clientSessionId", SESSION, "args", new JsonObject()));
		}
		if (pick < 10) {
			return notification(random.nextBoolean() ? "shutdown" : "exit", null);
		}
		if (pick < 11) {
			JsonObject response = new JsonObject();
			response.addProperty("jsonrpc", "2.0");
			response.addProperty("id", random.nextInt(5));
			response.add("result", JsonNull.INSTANCE);
			return response;
		}
		if (pick < 12) {
			return notification("$/cancelRequest", object("id", random.nextInt(2000)));
		}
		return process(action());
	}

	private JsonObject action() {
		return switch (random.nextInt(24)) {
			case 0, 1, 2 -> object("kind", "requestModel", "requestId", "", "options", object("sourceUri", uri(), "diagramType", DIAGRAM_TYPE,
					"needsClientLayout", true, "isReconnecting", false));
			case 3, 4 -> operation("changeBounds", "newBounds", array(object("elementId", id(), "newSize", size(), "newPosition", point())));
			case 5, 6 -> operation("createNode", "elementTypeId", pick(STATE_TYPES), "location", point(), "containerId", id(), "args", new JsonObject());
			case 7 -> operation("createEdge", "elementTypeId", "transition", "sourceElementId", id(), "targetElementId", id(), "args", new JsonObject());
			case 8, 9 -> operation("applyLabelEdit", "labelId", id() + (random.nextBoolean() ? "#name" : "#expression"), "text", labelText());
			case 10, 11 -> random.nextBoolean() ? object("kind", "saveModel") : object("kind", "saveModel", "fileUri", uri());
			case 12 -> object("kind", "requestPopupModel", "requestId", "popup", "elementId", id(), "bounds", bounds());
			case 13 -> object("kind", random.nextBoolean() ? "glspUndo" : "glspRedo");
			case 14 -> operation("deleteElement", "elementIds", array(new JsonPrimitive(id()), new JsonPrimitive(id())));
			case 15 -> operation("changeContainer", "elementId", id(), "targetContainerId", id(), "location", point());
			case 16 -> object("kind", "requestClipboardData", "requestId", "copy", "editorContext", context());
			case 17 -> operation("paste", "clipboardData", object("application/x-kse-states", pick(clipboardKeys), "text/plain", "x"), "editorContext",
					context());
			case 18 -> operation("cut", "editorContext", context());
			case 19 -> object("kind", "computedBounds", "revision", random.nextInt(50), "bounds",
					array(object("elementId", id(), "newSize", size(), "newPosition", point())), "alignments", new JsonArray(), "routes", new JsonArray());
			case 20 -> object("kind", "requestEditValidation", "requestId", "v", "contextId", random.nextInt(4) == 0 ? "\u001b[2J" : "label-edit", "modelElementId", id() + "#name", "text",
					labelText());
			case 21 -> operation("layout", "elementIds", array(new JsonPrimitive(id())));
			case 22 -> operation("compound", "operationList", array(operation("changeBounds", "newBounds",
					array(object("elementId", id(), "newSize", size(), "newPosition", point()))), operation("deleteElement", "elementIds",
							array(new JsonPrimitive(id())))));
			default -> switch (random.nextInt(6)) {
				case 0 -> object("kind", "requestMarkers", "requestId", "m", "elementsIDs", array(new JsonPrimitive(id())), "reason", "batch");
				case 1 -> operation("changeRoutingPoints", "newRoutingPoints", array(object("elementId", id(), "newRoutingPoints", array(point(), point()))));
				case 2 -> operation("reconnectEdge", "edgeElementId", id(), "sourceElementId", id(), "targetElementId", id(), "args", new JsonObject());
				case 3 -> object("kind", "setEditMode", "editMode", random.nextBoolean() ? "editable" : "readonly");
				case 4 -> object("kind", "requestContextActions", "requestId", "c", "contextId", "tool-palette", "editorContext", context());
				default -> object("kind", pick(KINDS));
			};
		};
	}

	private JsonObject request(String method, JsonElement params) {
		JsonObject request = notification(method, params);
		request.addProperty("id", nextId++);
		return request;
	}

	private static JsonObject notification(String method, JsonElement params) {
		JsonObject message = new JsonObject();
		message.addProperty("jsonrpc", "2.0");
		message.addProperty("method", method);
		if (params != null) {
			message.add("params", params);
		}
		return message;
	}

	static JsonObject process(JsonObject action) {
		return notification("process", object("clientId", SESSION, "action", action));
	}

	private JsonObject operation(String kind, Object... properties) {
		JsonObject operation = object(properties);
		operation.addProperty("kind", kind);
		operation.addProperty("isOperation", true);
		return operation;
	}

	private JsonObject context() {
		return object("selectedElementIds", array(new JsonPrimitive(id()), new JsonPrimitive(id())), "lastMousePosition", point(), "sourceUri", uri(),
				"args", new JsonObject());
	}

	private String id() {
		return pick(ids);
	}

	private String uri() {
		return pick(uris);
	}

	private String labelText() {
		return pick(List.of("Renamed", "Chase", "[a.b.C.d()==1]", "9Scan", "", " ", "a\nb", "a\u0001b", "<x>&\"'", "[TimeoutCheck(behavior.kicked)]",
				"x".repeat(2000), "\ud800", "\ud83e\udd16"));
	}

	private JsonObject point() {
		return object("x", coordinate(), "y", coordinate());
	}

	private JsonObject size() {
		return object("width", coordinate(), "height", coordinate());
	}

	private JsonObject bounds() {
		return object("x", coordinate(), "y", coordinate(), "width", coordinate(), "height", coordinate());
	}

	private Number coordinate() {
		return random.nextInt(4) == 0 ? (Number) hostileNumber() : (Number) (random.nextInt(1200) - 100);
	}

	// --- mutations ---

	/** Replaces, removes or adds one value somewhere in the message. */
	private void mutate(JsonObject message) {
		List<JsonObject> objects = new ArrayList<>();
		collect(message, objects);
		JsonObject target = pick(objects);
		List<String> keys = new ArrayList<>(target.keySet());
		switch (random.nextInt(6)) {
			case 0 -> {
				if (!keys.isEmpty()) {
					target.remove(pick(keys));
				}
			}
			case 1 -> target.add(pick(List.of("kind", "id", "method", "params", "clientId", "action", "sourceUri", "elementId", "extra", "__proto__")),
					hostile());
			default -> {
				if (!keys.isEmpty()) {
					target.add(pick(keys), hostile());
				}
			}
		}
	}

	private static void collect(JsonElement element, List<JsonObject> objects) {
		if (element instanceof JsonObject object) {
			objects.add(object);
			for (Map.Entry<String, JsonElement> entry : object.entrySet()) {
				collect(entry.getValue(), objects);
			}
		} else if (element instanceof JsonArray array) {
			for (JsonElement each : array) {
				collect(each, objects);
			}
		}
	}

	/** A value of any type that a handler does not expect. */
	private JsonElement hostile() {
		return switch (random.nextInt(16)) {
			case 0 -> JsonNull.INSTANCE;
			case 1 -> new JsonPrimitive(random.nextBoolean());
			case 2, 3 -> new JsonPrimitive(hostileNumber());
			case 4 -> new JsonPrimitive("x".repeat(random.nextInt(3) == 0 ? 60_000 : 300));
			case 5, 6 -> new JsonPrimitive(uri());
			case 7 -> new JsonPrimitive(id());
			case 8 -> new JsonPrimitive(pick(KINDS));
			case 9 -> new JsonPrimitive(pick(METHODS));
			case 10 -> new JsonArray();
			case 11 -> new JsonObject();
			case 12 -> nested(1 + random.nextInt(random.nextBoolean() ? 100 : 2000));
			case 13 -> new JsonPrimitive(pick(List.of("\u0000", "\n", "\u001b]0;kse\u0007\u001b[2J\u001b[31m", "\ud800", "\ufeff", "\u202e", "<script>alert(1)</script>", "${jndi:ldap://127.0.0.1/x}",
					"%s%n%x", "{}", "[]", "null", "NaN", "-0", "true")));
			case 14 -> object("kind", pick(KINDS), "elementId", id(), "clientId", SESSION);
			default -> array(new JsonPrimitive(id()), JsonNull.INSTANCE, new JsonPrimitive(hostileNumber()));
		};
	}

	private Number hostileNumber() {
		return switch (random.nextInt(12)) {
			case 0 -> 2147483648L;
			case 1 -> -2147483649L;
			case 2 -> new BigInteger("9223372036854775808");
			case 3 -> new BigInteger("123456789012345678901234567890123456789");
			case 4 -> 1e308;
			case 5 -> -1e308;
			case 6 -> new BigDecimal("1e999");
			case 7 -> new BigDecimal("-1e999");
			case 8 -> 4.9e-324;
			case 9 -> -1;
			case 10 -> 0.5;
			default -> 0;
		};
	}

	private static JsonElement nested(int depth) {
		JsonArray root = new JsonArray();
		JsonArray inner = root;
		for (int i = 1; i < depth; i++) {
			JsonArray next = new JsonArray();
			inner.add(next);
			inner = next;
		}
		return root;
	}

	private static final List<String> WORDS = List.of("{", "}", "[", "]", "\"", ":", ",", "\\", "\\u0000", "\\ud800", "null", "true", "1e999", "-0",
			"NaN", "Infinity", "99999999999999999999999", "\u0000", "\ufeff", "\"kind\":\"saveModel\"", "\"id\":null", "\"id\":{}", "\"clientId\":\"other\"",
			"\"sourceUri\":\"../outside/Outside.stct\"", "\\u001b[2J", "\u001b[31m", "\"fileUri\":\"/tmp/kse-fuzz-escaped.stct\"", "//@nodes.0", "#name", "\"jsonrpc\":\"1.0\"",
			"/*", "*/", "'", "\r\n");

	/** The message's text mutated as bytes: flipped, cut, truncated, repeated, moved, words of JSON inserted. */
	/** The message as text, mangled byte by byte (no longer JSON, or JSON of another meaning). */
	private String text(String message) {
		return bytes.mutate(message);
	}

	/** What no mutation of a real message makes: not JSON-RPC, deeply nested, huge, empty, a batch. */
	private String special() {
		List<Supplier<String>> specials = List.of( //
				() -> "", //
				() -> " ", //
				() -> "null", //
				() -> "42", //
				() -> "\"text\"", //
				() -> "[]", //
				() -> "{}", //
				() -> "[" + real() + "," + real() + "]", //
				() -> "[".repeat(100_000) + "]".repeat(100_000), //
				() -> "{\"a\":".repeat(30_000) + "1" + "}".repeat(30_000), //
				() -> process(object("kind", "compound", "isOperation", true, "operationList",
						nestedCompound(300 + random.nextInt(3000)))).toString(), //
				() -> "{\"jsonrpc\":\"2.0\",\"method\":\"process\",\"params\":" + nested(5_000) + "}", //
				() -> "{\"jsonrpc\":\"2.0\",\"id\":1,\"method\":\"initialize\",\"params\":{\"applicationId\":\"" + "x".repeat(2_000_000) + "\"}}", //
				() -> process(operation("applyLabelEdit", "labelId", id() + "#name", "text", "A".repeat(200_000))).toString(), //
				() -> {
					byte[] noise = new byte[random.nextInt(600)];
					random.nextBytes(noise);
					return new String(noise, StandardCharsets.ISO_8859_1);
				}, //
				() -> "{\"jsonrpc\":\"2.0\",\"id\":1,\"id\":2,\"method\":\"initialize\",\"method\":\"process\",\"params\":{}}", //
				() -> process(object("kind", "changeBounds", "isOperation", true, "newBounds", manyBounds(600))).toString());
		return pick(specials).get();
	}

	private JsonArray nestedCompound(int depth) {
		JsonObject inner = operation("glspUndo");
		for (int i = 0; i < depth; i++) {
			inner = object("kind", "compound", "isOperation", true, "operationList", array(inner));
		}
		return array(inner);
	}

	private JsonArray manyBounds(int count) {
		JsonArray all = new JsonArray();
		for (int i = 0; i < count; i++) {
			all.add(object("elementId", id(), "newPosition", point()));
		}
		return all;
	}

	// --- helpers ---

	private <T> T pick(List<T> list) {
		return list.get(random.nextInt(list.size()));
	}

	static JsonObject object(Object... properties) {
		JsonObject object = new JsonObject();
		for (int i = 0; i + 1 < properties.length; i += 2) {
			object.add((String) properties[i], json(properties[i + 1]));
		}
		return object;
	}

	private static JsonElement json(Object value) {
		if (value == null) {
			return JsonNull.INSTANCE;
		}
		if (value instanceof JsonElement element) {
			return element;
		}
		if (value instanceof Number number) {
			return new JsonPrimitive(number);
		}
		if (value instanceof Boolean bool) {
			return new JsonPrimitive(bool);
		}
		return new JsonPrimitive(value.toString());
	}

	private static JsonArray array(JsonElement... elements) {
		JsonArray array = new JsonArray();
		for (JsonElement element : elements) {
			array.add(element);
		}
		return array;
	}

	static JsonArray strings(List<String> values) {
		JsonArray array = new JsonArray();
		values.forEach(array::add);
		return array;
	}
}
