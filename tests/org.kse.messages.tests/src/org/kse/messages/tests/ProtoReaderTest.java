package org.kse.messages.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kse.messages.tests.Protos.assertNoProblems;
import static org.kse.messages.tests.Protos.at;
import static org.kse.messages.tests.Protos.parse;
import static org.kse.messages.tests.Protos.pos;
import static org.kse.messages.tests.Protos.problem;

import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.kse.messages.EnumType;
import org.kse.messages.Field;
import org.kse.messages.Field.Label;
import org.kse.messages.FieldType;
import org.kse.messages.MessageType;
import org.kse.messages.ProtoFile;
import org.kse.messages.ProtoImport;
import org.kse.messages.ProtoProblem;
import org.kse.messages.ScalarKind;

/** The reader on its own (grammar and checks): every construct of the supported subset, and syntax errors. */
class ProtoReaderTest {

	private static List<String> fieldNames(MessageType m) {
		return m.fields().stream().map(Field::name).toList();
	}

	@Test
	void proto2WorldInfoWithNestedMessages() {
		ProtoFile file = parse(Protos.WORLD_INFO);
		assertNoProblems(file.problems());
		assertEquals("proto2", file.syntax());
		assertEquals("", file.packageName());
		assertEquals(List.of("common.proto"), file.imports().stream().map(ProtoImport::path).toList());

		MessageType worldInfo = file.messages().get(0);
		assertEquals("WorldInfo", worldInfo.name());
		assertEquals("WorldInfo", worldInfo.fullName());
		assertEquals(List.of("myPosition", "balls", "header"), fieldNames(worldInfo));
		assertEquals(List.of("Position", "Ball"), worldInfo.nestedMessages().stream().map(MessageType::name).toList());

		MessageType position = worldInfo.nestedMessages().get(0);
		assertEquals("WorldInfo.Position", position.fullName());
		assertEquals(worldInfo, position.parent().orElseThrow());
		assertEquals(List.of("X", "Y", "phi", "confidence"), fieldNames(position));

		Field myPosition = worldInfo.field("myPosition").orElseThrow();
		assertEquals(1, myPosition.number());
		assertEquals(Label.REQUIRED, myPosition.label());
		assertEquals("Position", myPosition.typeName());
		assertEquals(new FieldType.Unresolved("Position"), myPosition.type(), "resolved only by a catalog");
		assertEquals(worldInfo, myPosition.containingType());
		assertEquals(Label.REPEATED, worldInfo.field("balls").orElseThrow().label());
		assertTrue(worldInfo.field("balls").orElseThrow().isRepeated());

		Field confidence = position.field("confidence").orElseThrow();
		assertEquals(Label.OPTIONAL, confidence.label());
		assertEquals(ScalarKind.FLOAT, confidence.scalarKind().orElseThrow());
		assertEquals(pos(Protos.WORLD_INFO, "confidence"), confidence.line() + ":" + confidence.column());
		assertEquals(pos(Protos.WORLD_INFO, "float confidence"), confidence.typeLine() + ":" + confidence.typeColumn());
	}

	@Test
	void topLevelEnumAndDefaultOptions() {
		ProtoFile file = parse(Protos.GAME_STATE);
		assertNoProblems(file.problems());
		EnumType state = file.enums().get(0);
		assertEquals("PlayerState", state.fullName());
		assertEquals(Map.of("PLAYER_INITIAL", 0, "PLAYER_READY", 1, "PLAYER_SET", 2, "PLAYER_PLAYING", 3,
				"PLAYER_FINISHED", 4, "PLAYER_PENALISED", 5), state.values());
		assertEquals(List.of("PLAYER_INITIAL", "PLAYER_READY", "PLAYER_SET", "PLAYER_PLAYING", "PLAYER_FINISHED",
				"PLAYER_PENALISED"), List.copyOf(state.values().keySet()), "declaration order");
		assertEquals(3, state.value("PLAYER_PLAYING").getAsInt());
		assertTrue(state.value("PLAYER_DANCING").isEmpty());
		assertEquals(List.of("GameStateMessage", "HeadToBMessage"),
				file.messages().stream().map(MessageType::name).toList());
		assertEquals(12, file.messages().get(0).fields().size());
	}

	@Test
	void proto3PackageMapOneofReservedServiceAndOptions() {
		ProtoFile file = parse(Protos.MOTION);
		assertNoProblems(file.problems());
		assertEquals("proto3", file.syntax());
		assertEquals("kse.motion", file.packageName());
		assertEquals(List.of("MotionWalkMessage", "Velocity"), file.messages().stream().map(MessageType::name).toList());

		MessageType walk = file.messages().get(0);
		assertEquals("kse.motion.MotionWalkMessage", walk.fullName());
		assertEquals(List.of("command", "parameter", "tuning", "pose", "velocity", "mode"), fieldNames(walk));
		assertEquals(Label.OPTIONAL, walk.field("command").orElseThrow().label(), "proto3 without label is singular");

		Field tuning = walk.field("tuning").orElseThrow();
		assertEquals(Label.MAP, tuning.label());
		assertEquals("string", tuning.mapKeyTypeName().orElseThrow());
		assertEquals("float", tuning.typeName());
		assertEquals(ScalarKind.FLOAT, tuning.scalarKind().orElseThrow());
		assertTrue(tuning.isRepeated());

		assertEquals("target", walk.field("pose").orElseThrow().oneof());
		assertEquals("target", walk.field("velocity").orElseThrow().oneof());
		assertEquals(".kse.motion.Velocity", walk.field("velocity").orElseThrow().typeName());
		assertEquals("", walk.field("mode").orElseThrow().oneof());

		assertEquals("kse.motion.MotionWalkMessage.Pose2D", walk.nestedMessages().get(0).fullName());
		EnumType mode = walk.nestedEnums().get(0);
		assertEquals("kse.motion.MotionWalkMessage.Mode", mode.fullName());
		assertEquals(List.of("MODE_UNSPECIFIED", "MODE_WALK", "MODE_STOP"), List.copyOf(mode.values().keySet()));
	}

	@Test
	void proto2ExtensionsExtendGroupsOfOptionsAndImportModifiers() {
		String text = """
				syntax = "proto2";
				package monas;
				import public "a/common.proto";
				import weak "b.proto";
				import "c" "/d.proto";
				option (my.file_option) = { name: "x;}" nested { depth: 2 } };

				message Sensors {
				  option (my.message_option) = true;
				  extensions 100 to max;
				  optional double sonar_left = 1 [(my.unit) = "m", deprecated = false];
				  reserved 2 to 4;
				  optional sint64 ticks = 5 [default = -1];
				  ;
				}

				extend Sensors {
				  optional int32 custom = 100;
				}

				enum Button {
				  option allow_alias = true;
				  reserved 7;
				  CHEST = 0;
				  PRESS = 1;
				  ALSO_PRESS = 1;
				  NEGATIVE = -2;
				  HEX = 0x1F;
				}
				""";
		ProtoFile file = parse(text);
		assertNoProblems(file.problems());
		assertEquals(List.of(new ProtoImport("a/common.proto", ProtoImport.Modifier.PUBLIC, 3, 15),
				new ProtoImport("b.proto", ProtoImport.Modifier.WEAK, 4, 13),
				new ProtoImport("c/d.proto", ProtoImport.Modifier.NONE, 5, 8)), file.imports());
		MessageType sensors = file.messages().get(0);
		assertEquals("monas.Sensors", sensors.fullName());
		assertEquals(List.of("sonar_left", "ticks"), fieldNames(sensors), "extend blocks add nothing to the message");
		assertEquals(ScalarKind.SINT64, sensors.field("ticks").orElseThrow().scalarKind().orElseThrow());
		assertEquals(Map.of("CHEST", 0, "PRESS", 1, "ALSO_PRESS", 1, "NEGATIVE", -2, "HEX", 31),
				file.enums().get(0).values());
	}

	@Test
	void commentsAndStringEscapes() {
		String text = """
				/* leading block comment
				   message Hidden { } */
				syntax /* inline */ = "proto3"; // trailing
				import "esc\\x61pe\\t\\101\\u00e9\\"q\\'\\\\.proto";
				// message AlsoHidden {}
				message /* here */ Visible { // comment after brace
				  int32 a = 1; /* int32 b = 2; */
				}
				""";
		ProtoFile file = parse(text);
		assertNoProblems(file.problems());
		assertEquals("proto3", file.syntax());
		assertEquals("escape\tA\u00e9\"q'\\.proto", file.imports().get(0).path());
		assertEquals(List.of("Visible"), file.messages().stream().map(MessageType::name).toList());
		assertEquals(List.of("a"), fieldNames(file.messages().get(0)));
	}

	@Test
	void singleQuotedStringsAndWindowsLineEnds() {
		ProtoFile file = parse("syntax = 'proto2';\r\nmessage A {\r\n  optional Missing m = 1 \r\n}\r\n");
		ProtoProblem missingSemicolon = problem(file.problems(), "expected ';'");
		assertEquals("3:25", at(missingSemicolon), "after '1' on line 3, with CRLF counted as one line break");
	}

	@Test
	void noSyntaxStatementMeansProto2() {
		ProtoFile file = parse("message A { optional int32 a = 1; }");
		assertNoProblems(file.problems());
		assertEquals("proto2", file.syntax());
	}

	@Test
	void messagesNestedSeveralLevels() {
		ProtoFile file = parse("""
				syntax = "proto3";
				package p;
				message A { message B { message C { enum E { E0 = 0; } E e = 1; } C c = 1; } B b = 1; }
				""");
		assertNoProblems(file.problems());
		MessageType c = file.messages().get(0).nestedMessages().get(0).nestedMessages().get(0);
		assertEquals("p.A.B.C", c.fullName());
		assertEquals("p.A.B.C.E", c.nestedEnums().get(0).fullName());
	}

	// ---- syntax errors: reported with positions, never thrown, and what was understood is kept

	@Test
	void missingSemicolonAtEndOfLineKeepsTheNextField() {
		String text = """
				syntax = "proto2";
				message A {
				  optional int32 x = 1
				  optional int32 y = 2;
				}
				""";
		ProtoFile file = parse(text);
		ProtoProblem p = problem(file.problems(), "expected ';' after field x");
		assertEquals("3:23", at(p));
		assertEquals(1, file.problems().size());
		assertEquals(List.of("x", "y"), fieldNames(file.messages().get(0)));
	}

	@Test
	void missingClosingBraceIsReportedAtTheEndOfFile() {
		String text = "syntax = \"proto2\";\nmessage A {\n  optional int32 x = 1;\n";
		ProtoFile file = parse(text);
		ProtoProblem p = problem(file.problems(), "missing '}' to close message A opened at 2:1");
		assertEquals("4:1", at(p));
		assertEquals(List.of("x"), fieldNames(file.messages().get(0)));
	}

	@Test
	void missingClosingBraceOfANestedMessage() {
		String text = """
				message Outer {
				  message Inner {
				    optional int32 i = 1;
				  optional int32 o = 2;
				}
				""";
		ProtoFile file = parse(text);
		assertEquals(1, file.problems().size(), () -> file.problems().toString());
		assertTrue(file.problems().get(0).message().contains("message Outer"));
		assertEquals(List.of("i", "o"), fieldNames(file.messages().get(0).nestedMessages().get(0)));
	}

	@ParameterizedTest
	@CsvSource(delimiter = '|', value = {
			"optional int32 x = 0;         | out of range",
			"optional int32 x = -3;        | out of range",
			"optional int32 x = 536870912; | out of range",
			"optional int32 x = 99999999999999999999; | out of range",
			"optional int32 x = 19500;     | reserved for the protocol buffer implementation",
			"optional int32 x = abc;       | expected a field number, found 'abc'",
			"optional int32 x = 1.5;       | expected a field number, found '1.5'",
			"optional int32 x = 09;        | invalid octal number '09'",
			"optional int32 x = ;          | expected a field number, found ';'",
	})
	void badFieldNumbersAreReportedAtTheNumber(String field, String expected) {
		String text = "message A {\n  " + field + "\n  optional int32 after = 2;\n}\n";
		ProtoFile file = parse(text);
		ProtoProblem p = problem(file.problems(), expected);
		String[] equals = pos(text, field.substring(field.indexOf('='))).split(":");
		assertEquals(equals[0] + ":" + (Integer.parseInt(equals[1]) + 2), at(p), "at the number, after '= '");
		assertEquals(1, file.problems().size(), () -> file.problems().toString());
		assertEquals(List.of("x", "after"), fieldNames(file.messages().get(0)));
	}

	@Test
	void otherErrorsCarryPositions() {
		String text = """
				syntax = "proto4";
				message { optional int32 lost = 1; }
				message Good {
				  optional int32 a = 1;
				  optional int32 b = 1;
				  optional string a = 3;
				  required map<int32, string> m = 4;
				  map<double, string> d = 5;
				  int32 nolabel = 6;
				  optional group G = 7 { optional int32 g = 1; }
				  oneof choice { optional int32 c = 8; message M {} }
				  optional int32 broken = 9 [deprecated = true;
				  optional int32 after = 10;
				  ) ;
				}
				enum Empty {}
				enum E { A = 1; A = 2; B = ; C }
				}
				$$$ ## 12abc 0x "unterminated
				/* never closed
				""";
		ProtoFile file = parse(text);
		List<ProtoProblem> ps = file.problems();
		assertEquals(pos(text, "\"proto4\""), at(problem(ps, "unknown syntax \"proto4\"")));
		assertEquals(pos(text, "{ optional int32 lost"), at(problem(ps, "expected a message name, found '{'")));
		assertEquals(pos(text, "b = 1"), at(problem(ps, "field number 1 of b is already used by a")));
		assertEquals(pos(text, "a = 3"), at(problem(ps, "duplicate field name a")));
		assertEquals(pos(text, "required map"), at(problem(ps, "map fields cannot have a label")));
		assertEquals(pos(text, "double, string"), at(problem(ps, "invalid map key type 'double'")));
		assertEquals(pos(text, "int32 nolabel"), at(problem(ps, "missing label")));
		assertEquals(pos(text, "group G"), at(problem(ps, "groups are not supported")));
		assertEquals(pos(text, "optional int32 c"), at(problem(ps, "fields in a oneof cannot have a label")));
		assertEquals(pos(text, "message M"), at(problem(ps, "only fields are allowed inside oneof choice")));
		assertEquals(pos(text, ";\n  optional int32 after"), at(problem(ps, "missing ']'")));
		assertEquals(pos(text, ") ;"), at(problem(ps, "found ')'")));
		assertEquals(pos(text, "Empty"), at(problem(ps, "enum Empty has no values")));
		assertEquals(pos(text, "A = 2"), at(problem(ps, "duplicate value A in enum E")));
		assertEquals(pos(text, "; C }"), at(problem(ps, "expected the number of enum value B")));
		assertEquals(pos(text, "}\n$$$"), at(problem(ps, "unmatched '}'")));
		assertEquals(pos(text, "$$$"), at(problem(ps, "unexpected characters '$$$'")));
		assertEquals(pos(text, "##"), at(problem(ps, "unexpected characters '##'")));
		assertEquals(pos(text, "12abc"), at(problem(ps, "invalid number '12abc'")));
		assertEquals(pos(text, "0x "), at(problem(ps, "hexadecimal number without digits")));
		assertEquals(pos(text, "\"unterminated"), at(problem(ps, "unterminated string")));
		assertEquals(pos(text, "/* never"), at(problem(ps, "unterminated comment")));

		MessageType good = file.messages().stream().filter(m -> m.name().equals("Good")).findFirst().orElseThrow();
		assertEquals(List.of("a", "b", "a", "m", "d", "nolabel", "c", "broken", "after"), fieldNames(good));
		assertEquals(Map.of("A", 1), file.enums().get(1).values());
		for (ProtoProblem p : ps) {
			assertTrue(p.line() >= 1 && p.column() >= 1, p::toString);
		}
	}

	@Test
	void syntaxMustComeFirstAndProto3RulesAreChecked() {
		String text = """
				message Early { }
				syntax = "proto3";
				""";
		ProtoFile file = parse(text);
		assertEquals(pos(text, "syntax"), at(problem(file.problems(), "must be the first statement")));
		// Even an empty statement comes too early, as for protoc (found by ProtocAgreementTest).
		String afterSemicolon = ";\nsyntax = \"proto2\";\n";
		assertEquals(pos(afterSemicolon, "syntax"),
				at(problem(parse(afterSemicolon).problems(), "must be the first statement")));

		String proto3 = """
				syntax = "proto3";
				enum E { ONE = 1; }
				message M { required int32 r = 1; }
				""";
		ProtoFile p3 = parse(proto3);
		assertEquals(pos(proto3, "1; }"), at(problem(p3.problems(), "first value of a proto3 enum must be zero")));
		assertEquals(pos(proto3, "required"), at(problem(p3.problems(), "'required' is not allowed in proto3")));
	}

	@Test
	void aFileImportedTwiceIsReportedOnce() {
		// protoc: Import "a.proto" was listed twice (found by ProtocAgreementTest).
		String text = """
				syntax = "proto2";
				import "a.proto";
				import public "a.proto";
				import "b.proto";
				""";
		ProtoFile file = parse(text);
		assertEquals(pos(text, "\"a.proto\";\nimport \"b"), at(problem(file.problems(), "imported twice")));
		assertEquals(List.of("a.proto", "b.proto"), file.imports().stream().map(ProtoImport::path).toList());
	}

	@Test
	void strayClosingBraceAtTopLevel() {
		ProtoFile file = parse("}\nmessage A { optional int32 a = 1; }\n}");
		assertEquals(2, file.problems().size());
		assertEquals("1:1", at(file.problems().get(0)));
		assertEquals("3:1", at(file.problems().get(1)));
		assertEquals(List.of("A"), file.messages().stream().map(MessageType::name).toList());
	}

	@Test
	void nullOrEmptyTextGivesAnEmptyFile() {
		ProtoFile empty = parse("");
		assertTrue(empty.messages().isEmpty() && empty.problems().isEmpty());
		ProtoFile nothing = parse(null);
		assertTrue(nothing.messages().isEmpty() && nothing.problems().isEmpty());
		assertFalse(parse("message").problems().isEmpty());
	}

	// ---- what the grammar adds over the hand-written reader

	@Test
	void keywordsAreNamesWhereProtocTakesThemAsNames() {
		String text = """
				syntax = "proto3";
				package message.option;
				message syntax {
				  int32 message = 1;
				  string option = 2;
				  bool syntax = 3;
				  repeated int32 map = 4;
				  optional int32 to = 5;
				  enum enum { reserved = 0; option = 1; max = 2; }
				  map<string, int32> stream = 7;
				}
				""";
		ProtoFile file = parse(text);
		assertNoProblems(file.problems());
		MessageType message = file.messages().get(0);
		assertEquals("message.option.syntax", message.fullName());
		assertEquals(List.of("message", "option", "syntax", "map", "to", "stream"), fieldNames(message));
		assertEquals(Map.of("reserved", 0, "option", 1, "max", 2), message.nestedEnums().get(0).values());
	}

	@Test
	void optionValuesOfEveryKindAreReadAndSkipped() {
		String text = """
				syntax = "proto2";
				import "google/protobuf/descriptor.proto";
				option (my.file) = { name: "x" size: -1.5e3 inner { flag: true } list: [1, 2, 3] [ext.field]: 7;
				                      any: < type_url: "t" > msgs [ { a: 1 }, { a: 2 } ] , nan_value: -inf };
				option java_package = "a" 'b';
				message M {
				  option (m).deep.(x.y) = 0x1F;
				  optional int32 a = 1 [default = -0x10, (v) = { a: 1 }, packed = false, json_name = "A"];
				  optional double d = 2 [default = .5];
				  optional string s = 3 [default = 's"x'];
				  extensions 100 to 199, 500 to max [(declaration) = { number: 100 }];
				  reserved 10, 12 to 14;
				  reserved "gone", "old";
				}
				extend M { optional int32 e = 100; }
				service S {
				  option (svc) = true;
				  rpc Get (M) returns (stream .M) { option deadline = 1.5; }
				  rpc Put (stream M) returns (M);
				  ;
				}
				""";
		ProtoFile file = parse(text);
		assertNoProblems(file.problems());
		assertEquals(List.of("a", "d", "s"), fieldNames(file.messages().get(0)));
	}

	@Test
	void aStrayTokenCostsOneProblemAndNothingAfterIt() {
		String text = """
				syntax = "proto2";
				42 "x" = ;
				message A {
				  optional int32 a = 1;
				  ) ] = 7 ;
				  optional int32 b = 2;
				}
				enum E { Z = 0; , . Y = 1; }
				message B { optional A a = 1; }
				""";
		ProtoFile file = parse(text);
		assertEquals(List.of("2:1: expected 'message', 'enum', 'import', 'package', 'option' or 'service', found '42'",
				"5:3: expected a field, 'message', 'enum' or 'oneof' in message A, found ')'",
				"8:17: expected an enum value in enum E, found ','"),
				file.problems().stream().map(p -> at(p) + ": " + p.message()).toList());
		assertEquals(List.of("A", "B"), file.messages().stream().map(MessageType::name).toList());
		assertEquals(List.of("a", "b"), fieldNames(file.messages().get(0)));
		assertEquals(Map.of("Z", 0, "Y", 1), file.enums().get(0).values());
	}

	@ParameterizedTest
	@CsvSource(delimiter = '|', value = {
			"message A { optional int32 = 1; }              | 1:28 | expected a field name, found '='",
			"message A { optional int32 x 1; }              | 1:30 | expected '=' after field name x, found '1'",
			"message A { optional int32 x = 1 }             | 1:33 | expected ';' after field x, found '}'",
			"message A { optional int32 x = 1; ; optional } | 1:46 | expected a field type after 'optional', found '}'",
			"message A { map<int32 string> m = 1; }         | 1:23 | expected ',' after the map key type, found 'string'",
			"enum E { A 0; }                                | 1:12 | expected '=' after enum value A, found '0'",
			"syntax 'proto2';                               | 1:8  | expected '=' after 'syntax', found string \"proto2\"",
			"syntax = proto2;                               | 1:10 | expected \"proto2\" or \"proto3\", found 'proto2'",
			"package ;                                      | 1:9  | expected a package name, found ';'",
			"import foo;                                    | 1:8  | expected the imported file name as a string, found 'foo'",
			"message A { optional B. = 1; }                 | 1:25 | expected a name after '.', found '='",
			"enum { A = 0; }                                | 1:6  | expected an enum name, found '{'",
			"message A { oneof { int32 x = 1; } }           | 1:19 | expected a oneof name, found '{'",
			"message A { oneof o { int32 x = 1; }           | 1:37 | missing '}' to close message A opened at 1:1",
			"option x = ;                                   | 1:12 | expected an option value, found ';'",
	})
	void syntaxErrorsSayWhatIsMissingWhereItIsMissing(String text, String where, String message) {
		ProtoFile file = parse(text);
		assertEquals(where + ": " + message, file.problems().isEmpty() ? "no problem" : at(file.problems().get(0)) + ": "
				+ file.problems().get(0).message(), () -> file.problems().toString());
	}
}
