package org.kse.messages.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kse.messages.MessageCatalog;
import org.kse.messages.ProtoFile;
import org.kse.messages.ProtoReader;
import org.kse.messages.ProtoProblem;

/**
 * Bad input of every kind: the parser must return (no exception, no hang, no stack overflow) and
 * every problem must point into the file.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class ProtoRobustnessTest {

	private static final String[] VOCABULARY = { "syntax", "=", "\"proto2\"", "\"proto3\"", "package", "import",
			"public", "weak", "option", "message", "enum", "service", "rpc", "returns", "extend", "oneof", "map", "<",
			">", ",", "reserved", "extensions", "to", "max", "optional", "required", "repeated", "group", "int32",
			"string", "float", "bool", "WorldInfo", "Position", "a.b.C", ".pkg.T", "x", "{", "}", "[", "]", "(", ")",
			";", ";", ";", "=", "1", "2", "-7", "0x1F", "019", "1.5e3", "99999999999999999999", "'single'",
			"\"esc\\x41\\u00e9\\101\"", "\"unterminated", "\"bad\\q\"", "// comment\n", "/* block */", "/* open",
			"\n", "\n", " ", "\t", "\r\n", "$", "#", "\u00e9", "\u0000", "\\", "@", "/", ".", "12abc", "0x" };

	private static final java.util.regex.Pattern JARGON = java.util.regex.Pattern
			.compile("RULE_|mismatched|extraneous|viable|<EOF>|missing EOF|required \\(\\.\\.\\.\\)\\+|T__");

	private static final String NOISE = "{}[]<>;=\"'/*\\\n\r.-0x9az";

	/** Parses, links into a catalog, and checks every problem's position; returns the parsed file. */
	static ProtoFile check(String text) {
		ProtoFile file = ProtoReader.read(Path.of("fuzz.proto"), text);
		long lines = lineBreaks(text) + 1;
		List<ProtoProblem> all = new ArrayList<>(file.problems());
		MessageCatalog catalog = MessageCatalog.of(List.of(file));
		all.addAll(catalog.problems());
		catalog.messages().forEach(m -> catalog.resolveMember(m, List.of("x", "y")));
		for (ProtoProblem p : all) {
			assertTrue(p.line() >= 1 && p.column() >= 1, () -> p + "\nin:\n" + text);
			assertTrue(p.line() <= lines + 1, () -> p + " beyond the end\nin:\n" + text);
			assertFalse(p.message().isBlank());
			// The parser's own words (token names, "mismatched input") never reach a user.
			assertFalse(JARGON.matcher(p.message()).find(), () -> p + "\nin:\n" + text);
		}
		return file;
	}

	/** Counted as the tokenizer does: "\r\n", "\n" and a lone "\r" each end a line. */
	private static long lineBreaks(String text) {
		return text.replace("\r\n", "\n").chars().filter(c -> c == '\n' || c == '\r').count();
	}

	@Test
	void randomTokenSequences() {
		Random random = new Random(20_12L);
		for (int i = 0; i < 3000; i++) {
			StringBuilder text = new StringBuilder();
			int length = random.nextInt(120);
			for (int t = 0; t < length; t++) {
				text.append(VOCABULARY[random.nextInt(VOCABULARY.length)]);
				if (random.nextInt(3) > 0) {
					text.append(' ');
				}
			}
			check(text.toString());
		}
	}

	@Test
	void randomCharacterNoise() {
		Random random = new Random(42);
		for (int i = 0; i < 1000; i++) {
			char[] chars = new char[random.nextInt(300)];
			for (int c = 0; c < chars.length; c++) {
				chars[c] = random.nextBoolean() ? NOISE.charAt(random.nextInt(NOISE.length()))
						: (char) random.nextInt(0x3000);
			}
			check(new String(chars));
		}
	}

	@Test
	void everyTruncationOfRealisticFiles() {
		for (String sample : List.of(Protos.WORLD_INFO, Protos.GAME_STATE, Protos.MOTION,
				"syntax = \"proto2\";\nimport public \"a\\\"b.proto\";\n/* c */ message A { oneof o { int32 i = 1; }"
						+ " map<string, A> m = 2 [deprecated = true]; }\nenum E { Z = 0 [(o) = \"x\"]; }\n")) {
			for (int end = 0; end <= sample.length(); end++) {
				check(sample.substring(0, end));
			}
		}
		// A truncated file keeps what came before the cut.
		String cut = Protos.WORLD_INFO.substring(0, Protos.WORLD_INFO.indexOf("repeated Ball"));
		ProtoFile file = check(cut);
		assertEquals(List.of("myPosition"), file.messages().get(0).fields().stream().map(f -> f.name()).toList());
		assertEquals(2, file.messages().get(0).nestedMessages().size());
	}

	@Test
	void randomMutationsOfARealisticFile() {
		Random random = new Random(7);
		String sample = Protos.MOTION + Protos.GAME_STATE;
		for (int i = 0; i < 2000; i++) {
			StringBuilder text = new StringBuilder(sample);
			for (int m = random.nextInt(5) + 1; m > 0; m--) {
				int at = random.nextInt(text.length());
				switch (random.nextInt(3)) {
				case 0 -> text.deleteCharAt(at);
				case 1 -> text.insert(at, VOCABULARY[random.nextInt(VOCABULARY.length)]);
				default -> text.setCharAt(at, NOISE.charAt(random.nextInt(NOISE.length())));
				}
			}
			check(text.toString());
		}
	}

	@Test
	void deepNestingNeitherOverflowsNorHangs() {
		int depth = 100_000;
		check("message A { ".repeat(depth));
		check("message A { ".repeat(depth) + "}".repeat(depth));
		check("{".repeat(depth));
		check("message A { optional int32 x = 1 " + "[".repeat(depth) + "; }");
		check("syntax = " + "\"a\" ".repeat(depth) + ";");
		check("/*".repeat(depth));
		check("}".repeat(depth));
		ProtoFile deep = check("message A { ".repeat(200) + "}".repeat(200));
		assertTrue(deep.problems().stream().anyMatch(p -> p.message().contains("nested more than")));
		assertTrue(deep.problems().size() <= 201, "problems are capped");
	}

	@Test
	void problemsAreCapped() {
		ProtoFile file = check("$ ".repeat(10_000));
		assertEquals(201, file.problems().size());
		assertTrue(file.problems().get(200).message().contains("too many problems"));
	}

	@Test
	void sameInputSameResult() {
		Random random = new Random(3);
		for (int i = 0; i < 200; i++) {
			StringBuilder text = new StringBuilder();
			for (int t = random.nextInt(80); t > 0; t--) {
				text.append(VOCABULARY[random.nextInt(VOCABULARY.length)]).append(' ');
			}
			String s = text.toString();
			assertEquals(ProtoReader.read(Path.of("f.proto"), s).problems(),
					ProtoReader.read(Path.of("f.proto"), s).problems());
		}
	}
}
