package org.kse.generator.monas.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.expression.ExpressionParser;
import org.kse.generator.monas.GenerationPlan;
import org.kse.generator.monas.MonasGenerator;
import org.kse.generator.monas.MonasGenerator.ModelHasErrorsException;
import org.kse.generator.monas.MonasGenerator.Options;
import org.kse.generator.monas.MonasGenerator.Report;
import org.kse.generator.monas.TreeMessages;
import org.kse.messages.StandardMessages;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.StatechartFactory;
import org.kse.model.statechart.Transition;
import org.kse.validation.ModelValidation;

/**
 * The generator's promises: golden output for a model with every node and action kind,
 * user code never overwritten, unchanged files never rewritten, nothing written outside
 * the source folder, keywords made valid, models with errors refused.
 * <p>
 * Golden files live in {@code golden/}; run with {@code -Dkse.updateGolden=true} to
 * rewrite them after an intended change, then read the diff.
 */
class GeneratorTest {

	private static final Path BUNDLE = Path.of(System.getProperty("kse.repository", "../..")).resolve("tests/org.kse.generator.monas.tests");

	private static Model allKinds() throws IOException {
		return StatechartResources.load(BUNDLE.resolve("models/AllKinds.stct"));
	}

	private static Map<Path, String> tree(Path root) throws IOException {
		Map<Path, String> files = new TreeMap<>();
		try (Stream<Path> walk = Files.walk(root)) {
			for (Path file : walk.filter(Files::isRegularFile).toList()) {
				files.put(root.relativize(file), Files.readString(file, StandardCharsets.UTF_8));
			}
		}
		return files;
	}

	@Test
	void generatesTheGoldenFiles(@TempDir Path folder) throws Exception {
		MonasGenerator.generate(allKinds(), folder, Options.DEFAULT);
		Map<Path, String> actual = tree(folder);
		Path golden = BUNDLE.resolve("golden/AllKinds");
		if (Boolean.getBoolean("kse.updateGolden")) {
			for (Map.Entry<Path, String> file : actual.entrySet()) {
				Files.createDirectories(golden.resolve(file.getKey()).getParent());
				Files.writeString(golden.resolve(file.getKey()), file.getValue());
			}
		}
		Map<Path, String> expected = tree(golden);
		assertEquals(expected.keySet(), actual.keySet(), "the generated files");
		for (Path file : expected.keySet()) {
			assertEquals(expected.get(file), actual.get(file), file.toString());
		}
	}

	@Test
	void everyNodeKindAndActionKindIsInTheOutput(@TempDir Path folder) throws Exception {
		MonasGenerator.generate(allKinds(), folder, Options.DEFAULT);
		String chart = Files.readString(folder.resolve("statecharts/AllKinds/AllKinds.cpp"));
		for (String kind : List.of("Add<StartState>", "Add<EndState>", "Add<ConditionConnector>", "Add<AndState>", "Add<OrState>", "Add<BasicState>")) {
			assertTrue(chart.contains(kind), kind);
		}
		assertTrue(chart.contains("Make<TimeoutAction>(\"behavior\", 100)"), "a lone timeout uses TimeoutAction");
		assertTrue(chart.contains("StatechartRegistrar<AllKinds> registrar(\"AllKinds\")"));
		String mixed = Files.readString(folder.resolve("statecharts/AllKinds/transitions/TrAction_0_3_TO_0_5.h"));
		assertTrue(mixed.contains("message.set_command(\"InitPose\");"));
		assertTrue(mixed.contains("_blk->Publish(\"motion\", kse::messaging::Kind::Signal, message);"));
		assertTrue(mixed.contains("statechart_engine::SetTimeout(*_blk, \"behavior\", std::chrono::milliseconds(50));"), mixed);
		String nullTest = Files.readString(folder.resolve("statecharts/AllKinds/transitions/TrCond_0_2_TO_0_3.h"));
		assertTrue(nullTest.contains("(msg0 == nullptr) || (msg0 != nullptr && msg0->ballfound() == 0)"), nullTest);
		String signal = Files.readString(folder.resolve("statecharts/AllKinds/transitions/TrCond_0_4_TO_0_5.h"));
		assertTrue(signal.contains("kse::messaging::Reader<FallMessage> msg0_;")
				&& signal.contains("msg0_.Bind(*_blk, \"worldstate\");")
				&& signal.contains("const auto msg0 = msg0_.ReadSignal();"), "a signal read through a reader bound once: " + signal);
		String activity = Files.readString(folder.resolve("activities/Search/Search.cpp"));
		assertTrue(activity.contains("[[maybe_unused]] const auto ball = _blk->ReadState<HeadToBMessage>(\"behavior\");"), activity);
		assertTrue(activity.contains("[[maybe_unused]] const auto world = _blk->ReadData<WorldInfo>(\"worldstate\");"), activity);
		assertTrue(activity.contains("_blk->Subscribe(\"behavior\");"), activity);
	}

	@Test
	void aTimeoutCheckGuardReadsThenProcessesMessagesThenDecides(@TempDir Path folder) throws Exception {
		MonasGenerator.generate(allKinds(), folder, Options.DEFAULT);
		Path transitions = folder.resolve("statecharts/AllKinds/transitions");
		String guard = Files.readString(transitions.resolve("TrCond_0_3_TO_0_3.h"));
		int timeoutRead = guard.indexOf("const auto timeout0 = timeout0_.ReadState();");
		int messageRead = guard.indexOf("const auto msg0 = msg0_.ReadState();");
		int processing = guard.indexOf("_blk->ProcessMessages();");
		int decision = guard.indexOf("const bool result = (statechart_engine::TimeoutCheck(*_blk, timeout0) && (msg0 != nullptr && ");
		assertTrue(timeoutRead > 0 && messageRead > 0 && processing > timeoutRead && processing > messageRead && decision > processing, guard);
		assertTrue(guard.contains("_blk->Subscribe(\"behavior\");") && guard.contains("_blk->Subscribe(\"worldstate\");"), "subscribes to the timer's topic too: " + guard);
		int bindings = guard.indexOf("timeout0_.Bind(*_blk, \"behavior\");\n\t\tmsg0_.Bind(*_blk, \"worldstate\");");
		assertTrue(bindings > guard.indexOf("void UserInit()") && bindings < guard.indexOf("bool Eval()"), "each reader is bound once, in UserInit(): " + guard);
		assertTrue(guard.contains("kse::messaging::Reader<TimeoutMsg> timeout0_;") && guard.contains("kse::messaging::Reader<GameStateMessage> msg0_;"), guard);
		assertTrue(guard.contains("#include <statechart_engine/TimeoutAction.h>"), guard);
		assertFalse(guard.contains("TimeoutExpired"), guard);
		for (String other : List.of("TrCond_0_2_TO_0_3.h", "TrCond_0_2_TO_0_4.h", "TrCond_0_3_TO_0_5.h", "TrCond_0_4_TO_0_5.h", "TrCond_0_4_2_2_TO_0_4_2_3.h")) {
			assertFalse(Files.readString(transitions.resolve(other)).contains("ProcessMessages"), other + ": only TimeoutCheck guards process messages");
		}
	}

	@Test
	void actionListsSetAndInitialiseTimersAndProcessMessages(@TempDir Path folder) throws Exception {
		MonasGenerator.generate(allKinds(), folder, Options.DEFAULT);
		String action = Files.readString(folder.resolve("statecharts/AllKinds/transitions/TrAction_0_3_TO_0_5.h"));
		int init = action.indexOf("void UserInit() override {\n\t\tstatechart_engine::InitTimeout(*_blk, \"behavior\");\n\t}");
		int execute = action.indexOf("void Execute() override {");
		assertTrue(init > 0 && execute > init, "UserInit publishes the empty TimeoutMsg: " + action);
		int publish = action.indexOf("_blk->Publish(\"motion\"");
		int processing = action.indexOf("_blk->ProcessMessages();");
		int timer = action.indexOf("statechart_engine::SetTimeout(*_blk, \"behavior\", std::chrono::milliseconds(50));");
		assertTrue(publish > execute && processing > publish && timer > processing, "the actions in the model's order: " + action);
		assertTrue(action.contains("// publish_all: nothing to send, each publish above reached the hub when it was made"), action);
		try (Stream<Path> walk = Files.walk(folder)) {
			for (Path file : walk.filter(Files::isRegularFile).toList()) {
				assertFalse(Files.readString(file).contains("always up to date"), file.toString());
			}
		}
		String chart = Files.readString(folder.resolve("statecharts/AllKinds/AllKinds.cpp"));
		assertTrue(chart.contains("definition->AddTransition(Node_0_1, Node_0_2, nullptr, Make<TimeoutAction>(\"behavior\", 100))"),
				"a list that is one TimeoutAction keeps the runtime's class: " + chart);
	}

	@Test
	void everyStateIsLabelledRightAfterItsDeclaration(@TempDir Path folder) throws Exception {
		Model model = allKinds();
		MonasGenerator.generate(model, folder, Options.DEFAULT);
		List<String> lines = Files.readAllLines(folder.resolve("statecharts/AllKinds/AllKinds.cpp"));
		java.util.regex.Pattern declaration = java.util.regex.Pattern.compile("\\t+(?:[A-Za-z]+State|ConditionConnector)\\* (Node_\\w+) = .*");
		List<String> labels = new ArrayList<>();
		for (int i = 0; i < lines.size(); i++) {
			var matcher = declaration.matcher(lines.get(i));
			if (matcher.matches()) {
				String next = lines.get(i + 1);
				assertTrue(next.strip().startsWith(matcher.group(1) + "->SetLabel(\""), lines.get(i) + " is followed by " + next);
				labels.add(next.substring(next.indexOf('"') + 1, next.lastIndexOf('"')));
			}
		}
		List<String> expected = new ArrayList<>();
		model.eAllContents().forEachRemaining(element -> {
			if (element instanceof Node node) {
				expected.add(node.getLabel());
			}
		});
		assertEquals(expected, labels);
	}

	@Test
	void loggerVariantAddsLoggingToConditionsOnly(@TempDir Path plain, @TempDir Path logged) throws Exception {
		MonasGenerator.generate(allKinds(), plain, Options.DEFAULT);
		MonasGenerator.generate(allKinds(), logged, new Options(true));
		String condition = "statecharts/AllKinds/transitions/TrCond_0_2_TO_0_3.h";
		assertFalse(Files.readString(plain.resolve(condition)).contains("std::clog"));
		assertTrue(Files.readString(logged.resolve(condition)).contains("std::clog << \"TrCond_0_2_TO_0_3 \""));
		assertEquals(Files.readString(plain.resolve("statecharts/AllKinds/AllKinds.cpp")),
				Files.readString(logged.resolve("statecharts/AllKinds/AllKinds.cpp")));
	}

	@Test
	void existingActivityCodeIsNeverOverwritten(@TempDir Path folder) throws Exception {
		MonasGenerator.generate(allKinds(), folder, Options.DEFAULT);
		Path search = folder.resolve("activities/Search/Search.cpp");
		String mine = "// my goalie code\nint mine = 1;\n";
		Files.writeString(search, mine);
		Files.delete(folder.resolve("activities/Search/CMakeLists.txt"));
		Report report = MonasGenerator.generate(allKinds(), folder, Options.DEFAULT);
		assertEquals(mine, Files.readString(search));
		assertFalse(Files.exists(folder.resolve("activities/Search/CMakeLists.txt")), "nothing is added inside an existing activity");
		assertTrue(report.kept().contains(Path.of("activities", "Search")), report.kept().toString());
	}

	@Test
	void unchangedFilesAreNotRewritten(@TempDir Path folder) throws Exception {
		MonasGenerator.generate(allKinds(), folder, Options.DEFAULT);
		FileTime past = FileTime.fromMillis(1_000_000_000_000L);
		List<Path> files;
		try (Stream<Path> walk = Files.walk(folder)) {
			files = walk.filter(Files::isRegularFile).toList();
		}
		for (Path file : files) {
			Files.setLastModifiedTime(file, past);
		}
		Report report = MonasGenerator.generate(allKinds(), folder, Options.DEFAULT);
		assertEquals(List.of(), report.written());
		assertFalse(report.unchanged().isEmpty());
		for (Path file : files) {
			assertEquals(past, Files.getLastModifiedTime(file), file.toString());
		}
	}

	/**
	 * A generation parses each expression once: the plan takes the parses of the validation
	 * before it, and transitions with one text share one parse.
	 */
	@Test
	void thePlanUsesTheValidationsParses() throws Exception {
		Path legacy = Path.of(System.getProperty("kse.repository", "../.."), "tests", "data", "legacy-kse");
		Model goalie = StatechartResources.load(legacy.resolve("Goalie/Goalie.stct"));
		ExpressionParser.Session session = ExpressionParser.session();
		ModelValidation.validate(goalie, StandardMessages.catalog(), session);
		int parsed = session.parsed();
		long texts = goalie.getTransitions().stream().map(Transition::getTE).filter(te -> te != null && !te.isBlank()).distinct().count();
		assertEquals(texts, parsed, "each text parsed once by the validation");
		GenerationPlan plan = GenerationPlan.of(goalie, StandardMessages.catalog(), TreeMessages.NONE, session);
		assertEquals(parsed, session.parsed(), "nothing parsed again by the plan");
		int withCondition = 0;
		for (GenerationPlan.PlannedTransition transition : plan.transitions()) {
			ExpressionParser.Result result = session.parse(transition.expression());
			assertSame(result.expression() == null ? null : result.expression().getCondition(), transition.condition(), transition.expression());
			withCondition += transition.condition() == null ? 0 : 1;
		}
		assertTrue(withCondition > 10, "the Goalie's guards are planned: " + withCondition);
	}

	@Test
	void outputIsDeterministic(@TempDir Path first, @TempDir Path second) throws Exception {
		MonasGenerator.generate(allKinds(), first, Options.DEFAULT);
		MonasGenerator.generate(allKinds(), second, Options.DEFAULT);
		assertEquals(tree(first), tree(second));
	}

	@Test
	void namesCannotEscapeTheSourceFolder(@TempDir Path sandbox) throws Exception {
		Path folder = sandbox.resolve("src");
		Model model = allKinds();
		model.setName("../../escape");
		node(model, "0.3").setName("../../../evil");
		Report report = MonasGenerator.generate(model, folder, Options.DEFAULT);
		try (Stream<Path> walk = Files.walk(sandbox)) {
			for (Path file : walk.filter(Files::isRegularFile).toList()) {
				assertTrue(file.normalize().startsWith(folder), "written outside the source folder: " + file);
			}
		}
		assertTrue(Files.isRegularFile(folder.resolve("statecharts/______escape/______escape.cpp")));
		assertTrue(Files.isRegularFile(folder.resolve("activities/_________evil/_________evil.cpp")));
		assertFalse(report.written().isEmpty());
	}

	/**
	 * Issue 13, items 1 and 5: tests/data/hostile/Hostile.stct validates, but its labels carry C++
	 * (a string's end and a call to system, a block comment's end and a declaration) and its
	 * names end in a backslash, which would make a line comment swallow the next line. No model
	 * text may become code (tests/integration/hostile compiles and runs the result).
	 */
	@Test
	void labelsAndNamesNeverBecomeCode(@TempDir Path folder) throws Exception {
		Model hostile = StatechartResources.load(Path.of(System.getProperty("kse.repository", "../.."), "tests", "data", "hostile", "Hostile.stct"));
		MonasGenerator.generate(hostile, folder, Options.DEFAULT);
		for (Map.Entry<Path, String> file : tree(folder).entrySet()) {
			String name = file.getKey().toString();
			assertTrue(name.matches("[A-Za-z0-9_./]+"), () -> "a file name made of model text: " + name);
			String text = file.getValue();
			String code = withoutLiteralsAndComments(text);
			assertFalse(code.contains("system("), () -> name + " calls what a label says:\n" + text);
			assertFalse(code.contains("int injected"), () -> name + " declares what a label says:\n" + text);
			for (String line : text.split("\n")) {
				assertFalse(line.contains("//") && line.endsWith("\\"), () -> name + ": a line comment continued on the next line: " + line);
			}
		}
		String chart = Files.readString(folder.resolve("statecharts/Hostile/Hostile.cpp"));
		assertTrue(chart.contains("->SetLabel(\"0.2\\\"); system(\\\"touch kse-injected\\\"); //\");"), chart);
		assertEquals(3, withoutLiteralsAndComments(chart).split("definition->AddTransition\\(", -1).length - 1, chart);
	}

	/** C++ text with its string literals and comments taken out: what the compiler reads as code. */
	private static String withoutLiteralsAndComments(String text) {
		StringBuilder code = new StringBuilder();
		int i = 0;
		while (i < text.length()) {
			if (text.startsWith("//", i)) {
				while (i < text.length() && text.charAt(i) != '\n') {
					i += text.charAt(i) == '\\' && i + 1 < text.length() ? 2 : 1; // a backslash joins the next line
				}
			} else if (text.startsWith("/*", i)) {
				int end = text.indexOf("*/", i + 2);
				i = end < 0 ? text.length() : end + 2;
			} else if (text.charAt(i) == '"') {
				i++;
				while (i < text.length() && text.charAt(i) != '"') {
					i += text.charAt(i) == '\\' ? 2 : 1;
				}
				i++;
				code.append("\"\"");
			} else {
				code.append(text.charAt(i++));
			}
		}
		return code.toString();
	}

	@Test
	void keywordsBecomeValidIdentifiers(@TempDir Path folder) throws Exception {
		Model model = allKinds();
		model.setName("int");
		node(model, "0.3").setName("class");
		node(model, "0.4.1.2").setName("2fast");
		MonasGenerator.generate(model, folder, Options.DEFAULT);
		assertTrue(Files.readString(folder.resolve("statecharts/int_/int_.h")).contains("class int_ : public statechart_engine::IStatechart"));
		assertTrue(Files.readString(folder.resolve("activities/class_/class_.h")).contains("class class_ : public statechart_engine::IActivity"));
		assertTrue(Files.isRegularFile(folder.resolve("activities/_2fast/_2fast.cpp")));
		assertTrue(Files.readString(folder.resolve("statecharts/int_/int_.cpp")).contains("ActivityFactory::Instance().PartNamed(\"class_\")"));
	}

	@Test
	void aModelWithErrorsIsRefusedAndNothingIsWritten(@TempDir Path folder) throws Exception {
		Model model = allKinds();
		Node orphanStart = StatechartFactory.eINSTANCE.createNode();
		orphanStart.setType("START");
		orphanStart.setLabel("0.6");
		orphanStart.setName("0.6");
		model.getNodes().get(0).getChildren().add(orphanStart);
		model.getTransitions().get(0).setTE("[worldstate.Stat.GameStateMessage==NULL]");
		ModelHasErrorsException refused = assertThrows(ModelHasErrorsException.class, () -> MonasGenerator.generate(model, folder, Options.DEFAULT));
		assertEquals(2, refused.errors().size(), refused.errors().toString());
		assertTrue(refused.errors().get(0).startsWith("0 (Striker): an OR state needs exactly one START state"), refused.errors().get(0));
		assertTrue(refused.errors().get(1).contains("expression 1:13"), refused.errors().get(1));
		try (Stream<Path> walk = Files.list(folder)) {
			assertEquals(List.of(), walk.toList());
		}
	}

	@Test
	void aModelWithAnEventIsRefusedInsteadOfGeneratingATransitionThatNeverFires(@TempDir Path folder) throws Exception {
		Model model = allKinds();
		model.getTransitions().get(5).setTE("Fallen[worldstate.Signal.FallMessage.fall()!=0]");
		ModelHasErrorsException refused = assertThrows(ModelHasErrorsException.class, () -> MonasGenerator.generate(model, folder, Options.DEFAULT));
		assertEquals(List.of("0.4->0.5 (Together_TO_0.5): expression 1:1: events are not supported: the engine never raises 'Fallen', so this"
				+ " transition would never fire (as in the original KSE); say in the condition what to wait for instead, as in"
				+ " [behavior.Signal.FallMessage.fall()!=0]"), refused.errors());
		try (Stream<Path> walk = Files.list(folder)) {
			assertEquals(List.of(), walk.toList(), "nothing written");
		}
	}

	@Test
	void staleTransitionClassesAreRemoved(@TempDir Path folder) throws Exception {
		Model model = allKinds();
		MonasGenerator.generate(model, folder, Options.DEFAULT);
		model.getTransitions().get(1).setTE("");
		Report report = MonasGenerator.generate(model, folder, Options.DEFAULT);
		assertEquals(List.of(Path.of("statecharts/AllKinds/transitions/TrCond_0_2_TO_0_3.h")), report.removed());
		assertFalse(Files.exists(folder.resolve("statecharts/AllKinds/transitions/TrCond_0_2_TO_0_3.h")));
	}

	@Test
	void theLegacyGoalieGenerates(@TempDir Path folder) throws Exception {
		Path legacy = Path.of(System.getProperty("kse.repository", "../.."), "tests", "data", "legacy-kse");
		Report report = MonasGenerator.generate(StatechartResources.load(legacy.resolve("Goalie/Goalie.stct")), folder, Options.DEFAULT);
		List<String> activities = new ArrayList<>();
		try (Stream<Path> list = Files.list(folder.resolve("activities"))) {
			list.map(p -> p.getFileName().toString()).sorted().forEach(activities::add);
		}
		assertEquals(List.of("ApproachBall", "GoToPosition", "Kick", "NoPlay", "Scan", "SpecialAction", "Stare"), activities);
		assertTrue(report.written().size() > 40);
	}

	@Test
	void theSourceTreesOwnMessagesAreCheckedIncludedAndBuilt(@TempDir Path folder) throws Exception {
		Model model = allKinds();
		model.getTransitions().get(1).setTE("[behavior.State.TeamMessage.role()==2]");
		ModelHasErrorsException unknown = assertThrows(ModelHasErrorsException.class, () -> MonasGenerator.generate(model, folder, Options.DEFAULT));
		assertTrue(unknown.errors().get(0).contains("expression 1:17: unknown message type 'TeamMessage'"), unknown.errors().toString());

		Files.createDirectories(folder.resolve("messages"));
		Files.writeString(folder.resolve("messages/Team.proto"), "syntax = \"proto2\";\nmessage TeamMessage { optional int32 role = 1; }\n");
		MonasGenerator.generate(model, folder, Options.DEFAULT);
		String condition = Files.readString(folder.resolve("statecharts/AllKinds/transitions/TrCond_0_2_TO_0_3.h"));
		assertTrue(condition.contains("#include \"Team.pb.h\""), condition);
		assertTrue(condition.contains("kse::messaging::Reader<TeamMessage> msg0_;") && condition.contains("msg0_.Bind(*_blk, \"behavior\");"), condition);
		String cmake = Files.readString(folder.resolve("statecharts/AllKinds/CMakeLists.txt"));
		assertTrue(cmake.contains("kse_add_messages(kse_user_messages"), cmake);
		assertTrue(cmake.contains("${CMAKE_CURRENT_SOURCE_DIR}/../../messages/Team.proto"), cmake);

		model.getTransitions().get(1).setTE("[behavior.State.TeamMessage.rank()==2]");
		ModelHasErrorsException field = assertThrows(ModelHasErrorsException.class, () -> MonasGenerator.generate(model, folder, Options.DEFAULT));
		assertTrue(field.errors().get(0).contains("'TeamMessage' has no field 'rank'"), field.errors().toString());
	}

	@Test
	void namesThatBecomeTheSameIdentifierAreErrorsNamingBoth(@TempDir Path folder) throws Exception {
		Model model = allKinds();
		node(model, "0.3").setName("a-b");
		node(model, "0.4.1.2").setName("a.b");
		ModelHasErrorsException refused = assertThrows(ModelHasErrorsException.class, () -> MonasGenerator.generate(model, folder, Options.DEFAULT));
		assertEquals(List.of("0.4.1.2 (a.b): its activity and that of 0.3 (a-b) both become the C++ class 'a_b' (only letters, digits and '_'"
				+ " are kept); rename one of them"), refused.errors());
		assertNothingWritten(folder);
	}

	@Test
	void namesThatDifferOnlyInCaseAreErrorsNamingBoth(@TempDir Path folder) throws Exception {
		Model model = allKinds();
		node(model, "0.3").setName("Scan");
		node(model, "0.4.1.2").setName("scan");
		ModelHasErrorsException refused = assertThrows(ModelHasErrorsException.class, () -> MonasGenerator.generate(model, folder, Options.DEFAULT));
		assertEquals(1, refused.errors().size(), refused.errors().toString());
		assertTrue(refused.errors().get(0).startsWith("0.4.1.2 (scan): its activity 'scan' and 'Scan' of 0.3 (Scan) differ only in case"),
				refused.errors().get(0));
		assertNothingWritten(folder);
	}

	@Test
	void anActivityNamedLikeItsStatechartIsAnError(@TempDir Path folder) throws Exception {
		Model model = allKinds();
		node(model, "0.3").setName("AllKinds");
		ModelHasErrorsException refused = assertThrows(ModelHasErrorsException.class, () -> MonasGenerator.generate(model, folder, Options.DEFAULT));
		assertEquals(List.of("0.3 (AllKinds): its activity 'AllKinds' has the name of the statechart's C++ class; rename the activity or the model"),
				refused.errors());
	}

	@Test
	void aNameTooLongForAFileIsRefusedBeforeAnythingIsWritten(@TempDir Path folder) throws Exception {
		Model model = allKinds();
		node(model, "0.4.2.2").setName("W".repeat(300));
		ModelHasErrorsException refused = assertThrows(ModelHasErrorsException.class, () -> MonasGenerator.generate(model, folder, Options.DEFAULT));
		assertEquals(List.of("0.4.2.2 (" + "W".repeat(300) + "): the name is 300 characters long; KSE's limit is 200 because it becomes a file name"),
				refused.errors());
		assertNothingWritten(folder);
		node(model, "0.4.2.2").setName("W".repeat(200));
		MonasGenerator.generate(model, folder, Options.DEFAULT);
		assertTrue(Files.isRegularFile(folder.resolve("activities/" + "W".repeat(200) + "/" + "W".repeat(200) + ".cpp")));
	}

	@Test
	void longLabelsGiveShortUniqueTransitionFiles(@TempDir Path folder) throws Exception {
		Model model = allKinds();
		for (var it = model.eAllContents(); it.hasNext();) {
			if (it.next() instanceof Node node) {
				node.setLabel(node.getLabel() + ".1".repeat(200));
			}
		}
		Report report = MonasGenerator.generate(model, folder, Options.DEFAULT);
		List<String> transitions = new ArrayList<>();
		try (Stream<Path> list = Files.list(folder.resolve("statecharts/AllKinds/transitions"))) {
			list.map(p -> p.getFileName().toString()).forEach(transitions::add);
		}
		assertFalse(transitions.isEmpty());
		transitions.forEach(name -> assertTrue(name.length() <= 140, name));
		assertEquals(transitions.size(), transitions.stream().map(String::toLowerCase).distinct().count(), transitions.toString());
		assertEquals(List.of(), MonasGenerator.generate(model, folder, Options.DEFAULT).written(), "the same names on the next run");
		assertTrue(report.written().size() > 5);
	}

	@Test
	void windowsDeviceNamesAreEscapedInAnyCase(@TempDir Path folder) throws Exception {
		Model model = allKinds();
		node(model, "0.3").setName("nul");
		node(model, "0.4.1.2").setName("Com1");
		MonasGenerator.generate(model, folder, Options.DEFAULT);
		assertTrue(Files.isRegularFile(folder.resolve("activities/nul_/nul_.h")));
		assertTrue(Files.isRegularFile(folder.resolve("activities/Com1_/Com1_.cpp")));
	}

	@Test
	void aKilledGenerationLeavesNoHalfMadeActivityAndTheNextRunCompletesIt(@TempDir Path folder) throws Exception {
		// What a run killed while writing leaves: a temporary file in a new activity folder (by an
		// older KSE), an activity being assembled, a temporary file beside the statechart.
		Files.createDirectories(folder.resolve("activities/Search"));
		Files.writeString(folder.resolve("activities/Search/.Search.h.0b1c.tmp"), "#ifndef");
		Files.createDirectories(folder.resolve("activities/.kse-staging-Track"));
		Files.writeString(folder.resolve("activities/.kse-staging-Track/Track.h"), "#ifndef");
		Files.createDirectories(folder.resolve("statecharts/AllKinds"));
		Files.writeString(folder.resolve("statecharts/AllKinds/.AllKinds.cpp.77aa.tmp"), "#include");
		Report report = MonasGenerator.generate(allKinds(), folder, Options.DEFAULT);
		assertEquals(List.of(), report.kept(), "nothing half-made is taken for the user's");
		for (String activity : List.of("Search", "Track", "Walk")) {
			try (Stream<Path> list = Files.list(folder.resolve("activities").resolve(activity))) {
				assertEquals(List.of("CMakeLists.txt", activity + ".cpp", activity + ".h"), list.map(p -> p.getFileName().toString()).sorted().toList());
			}
		}
		try (Stream<Path> list = Files.list(folder.resolve("activities"))) {
			assertEquals(List.of("Search", "Track", "Walk"), list.map(p -> p.getFileName().toString()).sorted().toList());
		}
		assertFalse(Files.exists(folder.resolve("statecharts/AllKinds/.AllKinds.cpp.77aa.tmp")));
		Files.writeString(folder.resolve("activities/Walk/Walk.cpp"), "// mine");
		assertEquals(3, MonasGenerator.generate(allKinds(), folder, Options.DEFAULT).kept().size());
		assertEquals("// mine", Files.readString(folder.resolve("activities/Walk/Walk.cpp")));
	}

	@Test
	void writesDoNotFollowASymbolicLinkOutOfTheTree(@TempDir Path temporary) throws Exception {
		Path folder = Files.createDirectories(temporary.resolve("tree"));
		Path elsewhere = Files.createDirectories(temporary.resolve("elsewhere"));
		Files.createSymbolicLink(folder.resolve("statecharts"), elsewhere);
		IOException refused = assertThrows(IOException.class, () -> MonasGenerator.generate(allKinds(), folder, Options.DEFAULT));
		assertTrue(refused.getMessage().startsWith("refusing to write outside " + folder.toAbsolutePath() + ": statecharts is a symbolic link to "),
				refused.getMessage());
		try (Stream<Path> list = Files.list(elsewhere)) {
			assertEquals(List.of(), list.toList());
		}
	}

	private static void assertNothingWritten(Path folder) throws IOException {
		try (Stream<Path> walk = Files.list(folder)) {
			assertEquals(List.of(), walk.toList(), "nothing written");
		}
	}

	private static Node node(Model model, String label) {
		for (var it = model.eAllContents(); it.hasNext();) {
			if (it.next() instanceof Node node && label.equals(node.getLabel())) {
				return node;
			}
		}
		throw new AssertionError("no state " + label);
	}
}
