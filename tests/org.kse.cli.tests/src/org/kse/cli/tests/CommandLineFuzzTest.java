package org.kse.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.testing.ByteMutator;

/**
 * Issue 13's fuzz suite for what a user hands to {@code kse}: formulas, statechart models, the
 * original tool's diagrams, transition expressions and a source tree's .proto files, each kind
 * {@link Fuzz#INPUTS} seeded variants of real files (the examples and the 2012 corpus), every
 * run held to the rules of {@link Fuzz}. What KSE writes it must read back: a model that
 * {@code transform} or {@code label} wrote is validated again, and must load.
 */
class CommandLineFuzzTest {

	@TempDir
	Path temporary;

	private static final Path LEGACY = Fuzz.REPOSITORY.resolve("tests/data/legacy-kse");
	private static final Path EXAMPLES = Fuzz.REPOSITORY.resolve("examples");

	/** Words that break parsers and generators; {@code REMOTE} becomes the address that must never be reached. */
	private static final List<String> COMMON = List.of("\n", "\r\n", "\t", " ", "\u0000", "\u00e9", "\u03a3\u03b1", "\ud83e\udd16", "\ufeff", "\\", "\"", "'", "*/",
			"/*", "//", "$(touch x)", "`id`", "99999999999", "2147483647", "-2147483648", "-1", "0", "1e999", "NaN", "../../../../tmp/kse-escaped",
			"C:\\", "nul", "CON", "REMOTE/x", "x".repeat(300));

	@Test
	void formulas() throws IOException {
		List<String> seeds = texts(Stream.of(EXAMPLES.resolve("Goalie/Goalie.liveness"), EXAMPLES.resolve("Attacker/Attacker.liveness"),
				EXAMPLES.resolve("Defender/Defender.liveness"), LEGACY.resolve("Goalie/Goalie.txt"), LEGACY.resolve("GUITester/GUITester.txt"),
				LEGACY.resolve("TestBehavior/TestBehavior.txt")));
		seeds.add("Tiny\nt = A.B\n");
		List<String> words = words("|", "||", "&", "~", "+", "*", "(", ")", "((((((((((((((((", "))))", "=", ".", ",", "|A~|2147483647", "|x~|99999999999",
				"|x~|0", "|x~|-3", "Wake.Chase~", "a = a", "b = c\nc = b", "_open_group_", "#", "\nx = \n", "Goalie", "goalie = x", "A.B.C");
		try (Fuzz fuzz = new Fuzz("formula", temporary.resolve("formula"))) {
			Random random = new Random(Fuzz.SEED);
			ByteMutator mutator = new ByteMutator(random, replace(words, fuzz));
			Path formula = fuzz.in.resolve("F.txt");
			for (int i = 0; i < Fuzz.INPUTS; i++) {
				byte[] input = mutator.mutate(seeds.get(random.nextInt(seeds.size())).getBytes(StandardCharsets.UTF_8));
				Files.write(formula, input);
				fuzz.clearOutput();
				Path model = fuzz.out.resolve("F.stct");
				Fuzz.Run run = fuzz.kse(i, input, "transform", "-q", formula.toString(), "-o", model.toString());
				if (run != null && run.code() == 0) {
					readsBack(fuzz, i, input, model);
				}
			}
			finish(fuzz);
		}
	}

	@Test
	void models() throws IOException {
		List<String> seeds = texts(seedModels());
		List<String> words = words("<", ">", "</", "/>", "&", "&amp;", "&#0;", "&#x1F;", "<![CDATA[", "]]>", "<!--", "-->", "\"/>", "=\"",
				"<!DOCTYPE m [<!ENTITY e SYSTEM \"REMOTE/e\">]>", "&e;", "<!DOCTYPE m [<!ENTITY a \"aaaaaaaaaa\"><!ENTITY b \"&a;&a;&a;&a;&a;&a;&a;&a;\">]>",
				" href=\"REMOTE/m.stct#//@nodes.0\"", " target=\"REMOTE/m.stct#//@nodes.0\"", " xmlns:statechart=\"REMOTE/ns\"",
				" source=\"//@nodes.0/@Children.99\"", " target=\"//@nodes.7/@Children.0/@Children.0\"", "//@nodes.0", "#//@transitions.0",
				" type=\"BASIC\"", " type=\"OR\"", " type=\"AND\"", " type=\"START\"", " type=\"END\"", " type=\"CONDITION\"", " type=\"XYZ\"",
				" label=\"0.1\"", " name=\"a-b\"", " name=\"Scan\"", " name=\"scan\"", " TE=\"[a.b.C.d()==1]\"", " TE=\"[\"", " variables=\"//@variables.9\"",
				"<Children name=\"x\" label=\"0.9\" type=\"BASIC\"/>", "<Children type=\"OR\"><Children type=\"OR\">", "</Children>",
				" xmi:id=\"x\"", " xmi:type=\"statechart:Node\"", " xsi:type=\"Nope\"", "<variables name=\"v\" type=\"a.b.C\"/>",
				"<transitions source=\"//@nodes.0\" target=\"//@nodes.0\"/>");
		try (Fuzz fuzz = new Fuzz("stct", temporary.resolve("stct"))) {
			Random random = new Random(Fuzz.SEED + 1);
			ByteMutator mutator = new ByteMutator(random, replace(words, fuzz));
			Path model = fuzz.in.resolve("M.stct");
			for (int i = 0; i < Fuzz.INPUTS; i++) {
				String seed = seeds.get(random.nextInt(seeds.size()));
				// Half of the inputs stay well-formed XML with hostile values, so they reach validation and generation.
				byte[] input = random.nextBoolean() ? mutateValues(seed, random, mutator).getBytes(StandardCharsets.UTF_8)
						: mutator.mutate(seed.getBytes(StandardCharsets.UTF_8));
				Files.write(model, input);
				fuzz.clearOutput();
				Fuzz.Run validate = fuzz.kse(i, input, "validate", model.toString());
				if (validate == null || validate.code() == 2) {
					continue;
				}
				Path labeled = fuzz.out.resolve("L.stct");
				Fuzz.Run label = fuzz.kse(i, input, "label", model.toString(), "-o", labeled.toString());
				if (label != null && label.code() == 0) {
					readsBack(fuzz, i, input, labeled);
				}
				if (validate.code() == 0) {
					fuzz.kse(i, input, "generate", "-q", model.toString(), fuzz.out.resolve("src").toString());
				}
			}
			finish(fuzz);
		}
	}

	@Test
	void legacyDiagrams() throws IOException {
		List<String> names = List.of("Goalie/Goalie", "GUITester/GUITester", "TestBehavior/TestBehavior", "TestBehavior/TestBehaviorInitial");
		List<String> words = words("<", ">", "/>", "&", "\"", " x=\"99999999999\"", " y=\"-2147483648\"", " width=\"-5\"", " height=\"1e999\"",
				" element=\"M.stct#//@nodes.0/@Children.99\"", " element=\"REMOTE/m.stct#//@nodes.0\"", " href=\"REMOTE/x.kse#/\"",
				"<children xmi:type=\"notation:Shape\">", "</children>", "<layoutConstraint xmi:type=\"notation:Bounds\" x=\"1\"/>", " type=\"2001\"",
				"<!DOCTYPE m [<!ENTITY e SYSTEM \"REMOTE/e\">]>", "&e;");
		try (Fuzz fuzz = new Fuzz("kse", temporary.resolve("kse"))) {
			Random random = new Random(Fuzz.SEED + 2);
			ByteMutator mutator = new ByteMutator(random, replace(words, fuzz));
			Path model = fuzz.in.resolve("M.stct");
			Path diagram = fuzz.in.resolve("M.kse");
			for (int i = 0; i < Fuzz.INPUTS; i++) {
				String name = names.get(random.nextInt(names.size()));
				Files.copy(LEGACY.resolve(name + ".stct"), model, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
				String original = Files.readString(LEGACY.resolve(name + ".kse")).replace(name.substring(name.indexOf('/') + 1) + ".stct#", "M.stct#");
				byte[] input = mutator.mutate(original.getBytes(StandardCharsets.UTF_8));
				Files.write(diagram, input);
				fuzz.clearOutput();
				fuzz.kse(i, input, "diagram", model.toString(), "-o", fuzz.out.resolve("M.svg").toString());
			}
			finish(fuzz);
		}
	}

	@Test
	void transitionExpressions() throws IOException {
		String goalie = Files.readString(LEGACY.resolve("Goalie/Goalie.stct"));
		List<String> seeds = new ArrayList<>();
		for (Path model : seedModels().toList()) {
			Matcher te = Pattern.compile(" TE=\"([^\"]*)\"").matcher(Files.readString(model));
			while (te.find()) {
				seeds.add(unescape(te.group(1)));
			}
		}
		List<String> words = words("[", "]", "/", ";", "&&", "||", "!", "==", "!=", "<=", ">=", "<", ">", "(", ")", ".", "()", "NULL",
				"worldstate.State.GameStateMessage.player_state()", "behavior.Signal.FallMessage.fall()", "TimeoutCheck(", "TimeoutAction.",
				"[TimeoutCheck(behavior.kicked)]/TimeoutAction.behavior.kicked.250", "worldstate.Data.", ".State.", "Event", "1e999", "0x7fffffff",
				"}; system(\"id\"); {", "\"); //", "((((((((((((((((((((", "!!!!!!!!!!!!!!!!");
		try (Fuzz fuzz = new Fuzz("expression", temporary.resolve("expression"))) {
			Random random = new Random(Fuzz.SEED + 3);
			ByteMutator mutator = new ByteMutator(random, replace(words, fuzz));
			Path model = fuzz.in.resolve("M.stct");
			Matcher slots = Pattern.compile(" TE=\"[^\"]*\"").matcher(goalie);
			List<int[]> places = new ArrayList<>();
			while (slots.find()) {
				places.add(new int[] { slots.start(), slots.end() });
			}
			for (int i = 0; i < Fuzz.INPUTS; i++) {
				String expression = mutator.mutate(seeds.get(random.nextInt(seeds.size())));
				int[] place = places.get(random.nextInt(places.size()));
				String text = goalie.substring(0, place[0]) + " TE=\"" + escape(expression) + "\"" + goalie.substring(place[1]);
				byte[] input = text.getBytes(StandardCharsets.UTF_8);
				Files.write(model, input);
				fuzz.clearOutput();
				Fuzz.Run validate = fuzz.kse(i, expression.getBytes(StandardCharsets.UTF_8), "validate", model.toString());
				if (validate != null && validate.code() == 0) {
					fuzz.kse(i, expression.getBytes(StandardCharsets.UTF_8), "generate", "-q", model.toString(), fuzz.out.resolve("src").toString());
				}
			}
			finish(fuzz);
		}
	}

	@Test
	void protoFiles() throws IOException {
		List<String> seeds = texts(Files.list(Fuzz.REPOSITORY.resolve("runtime/messages")).filter(p -> p.toString().endsWith(".proto")).sorted());
		seeds.add("syntax = \"proto2\";\nmessage TeamMessage { optional int32 role = 1; repeated string names = 2; }\n");
		List<String> words = words("message", "{", "}", ";", "=", "optional", "required", "repeated", "int32", "string", "bytes", "float",
				"import \"x.proto\";", "import \"../../../../etc/passwd\";", "import \"REMOTE/x.proto\";", "package a.b;", "syntax = \"proto3\";",
				"oneof o { int32 a = 9; }", "map<string, int32> m = 7;", "enum E { A = 0; }", "message M {", "message GameStateMessage {",
				"option java_package = \"x\";", "extend M { optional int32 z = 100; }", "reserved 2, 15, 9 to 11;", "= 536870912;", "[default = 3]");
		Path goalie = LEGACY.resolve("Goalie/Goalie.stct");
		try (Fuzz fuzz = new Fuzz("proto", temporary.resolve("proto"))) {
			Random random = new Random(Fuzz.SEED + 4);
			ByteMutator mutator = new ByteMutator(random, replace(words, fuzz));
			for (int i = 0; i < Fuzz.INPUTS; i++) {
				byte[] input = mutator.mutate(seeds.get(random.nextInt(seeds.size())).getBytes(StandardCharsets.UTF_8));
				fuzz.clearOutput();
				Path source = fuzz.out.resolve("src");
				Files.createDirectories(source.resolve("messages"));
				Files.write(source.resolve("messages/Fuzz.proto"), input);
				Fuzz.Run validate = fuzz.kse(i, input, "validate", goalie.toString(), source.toString());
				// Generation reads the files as validation does; it runs on a tenth of them to keep the suite short.
				if (validate != null && validate.code() == 0 && i % 10 == 0) {
					fuzz.kse(i, input, "generate", "-q", goalie.toString(), source.toString());
				}
			}
			finish(fuzz);
		}
	}

	/** What KSE wrote, it reads back: validation may find problems in the model, but never fails to load it. */
	private static void readsBack(Fuzz fuzz, int index, byte[] input, Path model) {
		Fuzz.Run again = fuzz.kse(index, input, "validate", model.toString());
		if (again != null && again.code() == 2) {
			fuzz.fail(index, input, "KSE cannot read back the model it wrote:\n" + again.all());
		}
	}

	private static void finish(Fuzz fuzz) {
		System.out.println(fuzz.summary());
		assertEquals(List.of(), fuzz.failures().stream().limit(20).toList(), fuzz.summary() + "; inputs saved in target/fuzz-failures");
	}

	private static Stream<Path> seedModels() throws IOException {
		return Stream.of(LEGACY.resolve("Goalie/Goalie.stct"), LEGACY.resolve("GUITester/GUITester.stct"), LEGACY.resolve("TestBehavior/TestBehavior.stct"),
				EXAMPLES.resolve("Goalie/Goalie.stct"), EXAMPLES.resolve("Attacker/Attacker.stct"), EXAMPLES.resolve("Defender/Defender.stct"));
	}

	private static List<String> texts(Stream<Path> files) {
		List<String> texts = new ArrayList<>();
		files.forEach(file -> {
			try {
				texts.add(Files.readString(file));
			} catch (IOException e) {
				throw new java.io.UncheckedIOException(e);
			}
		});
		return texts;
	}

	private static List<String> words(String... kindWords) {
		List<String> all = new ArrayList<>(COMMON);
		all.addAll(List.of(kindWords));
		return all;
	}

	private static List<String> replace(List<String> words, Fuzz fuzz) {
		return words.stream().map(word -> word.replace("REMOTE", fuzz.remote())).toList();
	}

	/** Replaces one to three attribute values with a mutation of themselves or a word of the dictionary, escaped. */
	private static String mutateValues(String xml, Random random, ByteMutator mutator) {
		Matcher values = Pattern.compile(" ([\\w:]+)=\"([^\"]*)\"").matcher(xml);
		List<int[]> places = new ArrayList<>();
		while (values.find()) {
			places.add(new int[] { values.start(2), values.end(2) });
		}
		String text = xml;
		for (int k = 1 + random.nextInt(3); k > 0 && !places.isEmpty(); k--) {
			int[] place = places.remove(places.size() - 1 - random.nextInt(places.size()));
			String value = unescape(text.substring(place[0], place[1]));
			text = text.substring(0, place[0]) + escape(mutator.mutate(value)) + text.substring(place[1]);
		}
		return text;
	}

	private static String escape(String text) {
		StringBuilder out = new StringBuilder();
		text.codePoints().forEach(c -> {
			switch (c) {
				case '&' -> out.append("&amp;");
				case '<' -> out.append("&lt;");
				case '"' -> out.append("&quot;");
				case '\n' -> out.append("&#xA;");
				case '\r' -> out.append("&#xD;");
				case '\t' -> out.append("&#x9;");
				default -> {
					if (c >= 0x20 && c != 0xfffe && c != 0xffff && !(c >= 0xd800 && c <= 0xdfff)) {
						out.appendCodePoint(c);
					}
				}
			}
		});
		return out.toString();
	}

	private static String unescape(String xml) {
		return xml.replace("&quot;", "\"").replace("&lt;", "<").replace("&gt;", ">").replace("&#xA;", "\n").replace("&amp;", "&");
	}
}
