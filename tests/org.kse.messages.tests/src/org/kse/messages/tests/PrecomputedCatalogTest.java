package org.kse.messages.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.kse.messages.EnumType;
import org.kse.messages.Field;
import org.kse.messages.FieldType;
import org.kse.messages.MessageCatalog;
import org.kse.messages.MessageType;
import org.kse.messages.PrecomputedCatalog;
import org.kse.messages.ProtoFile;
import org.kse.messages.ProtoReader;
import org.kse.messages.ProtoType;
import org.kse.messages.StandardMessages;

/**
 * The standard messages the build wrote into the bundle (ADR 0030) are what parsing the bundled
 * {@code .proto} files gives, field for field and position for position, before and after linking;
 * data made from other texts is never used.
 */
class PrecomputedCatalogTest {

	private static List<String> standardTexts() {
		return StandardMessages.FILES.stream().map(StandardMessages::text).toList();
	}

	private static List<ProtoFile> parsedStandard() {
		return StandardMessages.FILES.stream()
				.map(name -> ProtoReader.read(Path.of(StandardMessages.FOLDER + name), StandardMessages.text(name))).toList();
	}

	@Test
	void theBundleCarriesTheStandardFilesAsTheGrammarReadsThem() {
		List<ProtoFile> bundled = PrecomputedCatalog.bundled()
				.orElseThrow(() -> new AssertionError("org.kse.messages lacks org/kse/messages/standard/catalog.bin, or it was"
						+ " made from other .proto texts than the bundled ones: the build step of bundles/org.kse.messages/pom.xml did not run"));
		List<ProtoFile> parsed = parsedStandard();
		assertEquals(describe(parsed), describe(bundled));
		assertTrue(bundled.stream().mapToLong(f -> f.messages().size()).sum() >= 10, "the standard messages are there: " + describe(bundled));
	}

	@Test
	void linkedTheyMakeTheSameCatalog() {
		MessageCatalog fromData = MessageCatalog.of(PrecomputedCatalog.bundled().orElseThrow());
		MessageCatalog fromParse = MessageCatalog.of(parsedStandard());
		assertEquals(describe(fromParse), describe(fromData));
		assertEquals(List.of(), fromData.problems());
		// what the validator asks for: a nested field's resolved type and an enum constant
		Field balls = fromData.message("WorldInfo").orElseThrow().field("balls").orElseThrow();
		assertTrue(balls.isRepeated() && balls.messageType().isPresent(), balls.toString());
		assertEquals(describe(StandardMessages.catalog()), describe(fromParse), "what StandardMessages hands out");
	}

	@Test
	void everyCallGivesFreshObjects() {
		// a catalog resolves field types in place: two reads must not share a field
		MessageType first = PrecomputedCatalog.bundled().orElseThrow().get(0).messages().get(0);
		MessageType second = PrecomputedCatalog.bundled().orElseThrow().get(0).messages().get(0);
		assertNotSame(first, second);
		assertNotSame(first.fields().get(0), second.fields().get(0));
	}

	@Test
	void dataMadeFromOtherTextsIsRefused() {
		List<String> texts = standardTexts();
		byte[] data = PrecomputedCatalog.encode(parsedStandard(), texts);
		assertTrue(PrecomputedCatalog.decode(data, texts).isPresent());

		List<String> edited = new ArrayList<>(texts);
		edited.set(1, edited.get(1) + "message Added { optional int32 a = 1; }\n");
		assertFalse(PrecomputedCatalog.decode(data, edited).isPresent(), "a standard file changed after the data was made");
		assertFalse(PrecomputedCatalog.decode(data, texts.subList(0, 3)).isPresent(), "a standard file fewer");
		assertFalse(PrecomputedCatalog.decode(Arrays.copyOf(data, data.length - 7), texts).isPresent(), "truncated");
		assertFalse(PrecomputedCatalog.decode(Arrays.copyOf(data, data.length + 1), texts).isPresent(), "trailing bytes");
		assertFalse(PrecomputedCatalog.decode(new byte[] { 1, 2, 3 }, texts).isPresent(), "not this format");
		byte[] garbled = data.clone();
		for (int i = 40; i < garbled.length; i += 13) {
			garbled[i] ^= (byte) 0x5a;
		}
		assertFalse(PrecomputedCatalog.decode(garbled, texts).isPresent(), "garbled bytes are refused, never thrown");
	}

	@Test
	void everythingTheReaderMakesSurvivesTheRoundTrip() {
		// proto3, a package, map, oneof, nested types, imports of each kind and problems: more
		// than the standard files use today, so that a new standard file cannot lose anything
		String withProblems = """
				syntax = "proto2";
				import public "a.proto";
				import weak "b.proto";
				import "c.proto";
				message Ünïcode { optional int32 x = 1; required Nope y = 2; optional int32 x = 3; }
				enum Empty {}
				message Broken { optional int32 = 4; }
				""";
		List<String> texts = List.of(Protos.MOTION, Protos.WORLD_INFO, Protos.GAME_STATE, withProblems);
		List<ProtoFile> files = List.of(ProtoReader.read(Path.of("kse/motion.proto"), texts.get(0)),
				ProtoReader.read(Path.of("world.proto"), texts.get(1)), ProtoReader.read(Path.of("a/b/game.proto"), texts.get(2)),
				ProtoReader.read(Path.of("bad.proto"), texts.get(3)));
		assertFalse(files.get(3).problems().isEmpty(), "the last sample has problems to carry");
		List<ProtoFile> decoded = PrecomputedCatalog.decode(PrecomputedCatalog.encode(files, texts), texts).orElseThrow();
		assertEquals(describe(files), describe(decoded));
		assertEquals(describe(MessageCatalog.of(files)), describe(MessageCatalog.of(decoded)));
	}

	// ---- a text of everything a catalog user can see, so that a difference shows where it is

	private static String describe(List<ProtoFile> files) {
		StringBuilder text = new StringBuilder();
		for (ProtoFile file : files) {
			text.append("file ").append(file.file()).append(' ').append(file.syntax()).append(" package '")
					.append(file.packageName()).append("'\n");
			file.imports().forEach(i -> text.append("  import ").append(i).append('\n'));
			file.messages().forEach(m -> describe(m, "  ", text));
			file.enums().forEach(e -> describe(e, "  ", text));
			file.problems().forEach(p -> text.append("  problem ").append(p).append('\n'));
		}
		return text.toString();
	}

	private static String describe(MessageCatalog catalog) {
		StringBuilder text = new StringBuilder(describe(catalog.files()));
		catalog.messages().forEach(m -> text.append("catalog ").append(m.fullName()).append('\n'));
		catalog.enums().forEach(e -> text.append("catalog ").append(e.fullName()).append('\n'));
		catalog.problems().forEach(p -> text.append("catalog problem ").append(p).append('\n'));
		return text.toString();
	}

	private static void describe(MessageType message, String indent, StringBuilder text) {
		text.append(indent).append(type(message)).append('\n');
		for (Field f : message.fields()) {
			text.append(indent).append("  field ").append(f).append(" label ").append(f.label()).append(" type '")
					.append(f.typeName()).append("' key ").append(f.mapKeyTypeName().orElse("-")).append(" oneof '")
					.append(f.oneof()).append("' at ").append(f.line()).append(':').append(f.column()).append(" type at ")
					.append(f.typeLine()).append(':').append(f.typeColumn()).append(" in ").append(f.containingType().fullName())
					.append(" -> ").append(resolved(f.type())).append('\n');
		}
		message.nestedMessages().forEach(m -> describe(m, indent + "  ", text));
		message.nestedEnums().forEach(e -> describe(e, indent + "  ", text));
	}

	private static void describe(EnumType type, String indent, StringBuilder text) {
		text.append(indent).append(type(type)).append(' ').append(type.values()).append('\n');
	}

	private static String type(ProtoType type) {
		return type + " (" + type.name() + ") " + type.file() + ":" + type.line() + ":" + type.column() + " in "
				+ type.parent().map(ProtoType::fullName).orElse("-");
	}

	private static String resolved(FieldType type) {
		return switch (type) {
		case FieldType.Scalar s -> "scalar " + s.kind();
		case FieldType.Message m -> type(m.type());
		case FieldType.Enum e -> type(e.type());
		case FieldType.Unresolved u -> "unresolved " + u.name();
		};
	}
}
