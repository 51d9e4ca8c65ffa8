package org.kse.model.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;
import org.kse.model.NodeKind;
import org.kse.model.StatechartRules;

/** The rule book: what the thesis says of each kind, and the C++ runtime's kinds are the same six. */
class StatechartRulesTest {

	private static final Path REPOSITORY = Path.of(System.getProperty("kse.repository", "../.."));

	@Test
	void anOrStateHoldsAnyStateAnAndStateOnlyOrRegionsTheOthersNone() {
		assertEquals(EnumSet.allOf(NodeKind.class), StatechartRules.mayHold(NodeKind.OR));
		assertEquals(EnumSet.of(NodeKind.OR), StatechartRules.mayHold(NodeKind.AND));
		for (NodeKind leaf : EnumSet.of(NodeKind.BASIC, NodeKind.START, NodeKind.END, NodeKind.CONDITION)) {
			assertTrue(StatechartRules.mayHold(leaf).isEmpty(), leaf.name());
		}
		assertEquals("a BASIC state cannot hold other states", StatechartRules.holdRefusal(NodeKind.BASIC, NodeKind.BASIC));
		assertEquals("an END state cannot hold other states", StatechartRules.holdRefusal(NodeKind.END, NodeKind.OR));
		assertEquals("an AND state holds only OR regions, not BASIC states", StatechartRules.holdRefusal(NodeKind.AND, NodeKind.BASIC));
		assertNull(StatechartRules.holdRefusal(NodeKind.AND, NodeKind.OR));
		assertEquals("a CONDITION state cannot hold other states", StatechartRules.leafRefusal(NodeKind.CONDITION));
		assertNull(StatechartRules.leafRefusal(NodeKind.AND), "an AND state holds regions");
		assertNull(StatechartRules.leafRefusal(NodeKind.OR));
		for (NodeKind child : NodeKind.values()) {
			assertNull(StatechartRules.holdRefusal(NodeKind.OR, child), child.name());
			assertEquals(StatechartRules.mayHold(NodeKind.AND).contains(child), StatechartRules.holdRefusal(NodeKind.AND, child) == null, child.name());
		}
	}

	@Test
	void noTransitionEntersAStartOrLeavesAnEnd() {
		for (NodeKind kind : NodeKind.values()) {
			assertEquals(kind != NodeKind.START, StatechartRules.mayEnter(kind), kind.name());
			assertEquals(kind != NodeKind.END, StatechartRules.mayLeave(kind), kind.name());
		}
		assertEquals("no transition enters a START state", StatechartRules.transitionRefusal(NodeKind.BASIC, NodeKind.START));
		assertEquals("no transition leaves an END state", StatechartRules.transitionRefusal(NodeKind.END, NodeKind.BASIC));
		assertNull(StatechartRules.transitionRefusal(NodeKind.START, NodeKind.END));
		assertNull(StatechartRules.transitionRefusal(NodeKind.CONDITION, NodeKind.CONDITION));
	}

	@Test
	void theRootIsAnOrStateWithOneStartAndAtMostOneEnd() {
		assertNull(StatechartRules.rootRefusal("OR"));
		assertEquals("the root state must be an OR state, not AND", StatechartRules.rootRefusal("AND"));
		assertEquals("the root state must be an OR state, not a state without a type", StatechartRules.rootRefusal(null));
		assertNull(StatechartRules.startCountRefusal(1));
		assertNotNull(StatechartRules.startCountRefusal(0));
		assertNotNull(StatechartRules.startCountRefusal(2));
		assertNull(StatechartRules.endCountRefusal(0));
		assertNull(StatechartRules.endCountRefusal(1));
		assertNotNull(StatechartRules.endCountRefusal(2));
	}

	@Test
	void everyKindHasACaptionAndAnIconAndThePaletteOffersEachOnce() {
		for (NodeKind kind : NodeKind.values()) {
			assertTrue(!kind.caption().isBlank() && !kind.icon().isBlank(), kind.name());
			assertEquals(kind, NodeKind.of(kind.name()));
		}
		assertEquals(EnumSet.allOf(NodeKind.class), EnumSet.copyOf(NodeKind.THESIS_ORDER));
		assertEquals(NodeKind.values().length, NodeKind.THESIS_ORDER.size());
		assertNull(NodeKind.of("XOR"));
	}

	/** The C++ runtime is a library of its own with its own checks; its kinds are ours. */
	@Test
	void theRuntimeKnowsTheSameKinds() throws IOException {
		String header = Files.readString(REPOSITORY.resolve("runtime/include/statechart_engine/States.h"));
		Matcher declaration = Pattern.compile("enum class StateKind \\{([^}]*)\\}").matcher(header);
		assertTrue(declaration.find(), "States.h declares enum class StateKind");
		Set<String> runtime = Arrays.stream(declaration.group(1).split(",")).map(String::strip).map(name -> name.toUpperCase(Locale.ROOT))
				.collect(Collectors.toCollection(TreeSet::new));
		Set<String> model = Arrays.stream(NodeKind.values()).map(NodeKind::name).collect(Collectors.toCollection(TreeSet::new));
		assertEquals(model, runtime);
	}
}
