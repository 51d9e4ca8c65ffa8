package org.kse.model.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.util.EcoreUtil;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.StatechartFactory;
import org.kse.model.statechart.Transition;
import org.kse.testing.NetworkTrap;

/**
 * A model KSE saves always opens again, however many {@code &&} and quotes its guards hold: the
 * JDK's parser counted each {@code &amp;} and {@code &quot;} against a limit of 100,000 and refused
 * a large model KSE had just saved, so the user lost it. With DOCTYPEs refused outright, those
 * counts only ever see the five predefined entities and the limit is lifted for model files. The
 * refusal of a DOCTYPE says where it is and is the same whichever reader saw the file.
 */
class EntitiesAndDoctypesTest {

	private static final String HEADER = "<?xml version=\"1.0\" encoding=\"ASCII\"?>\n";
	private static final String ROOT = "<statechart:Model xmi:version=\"2.0\" xmlns:xmi=\"http://www.omg.org/XMI\" xmlns:statechart=\"http://statechart/1.0\"";
	private static final String REFUSED = ": a model file may not declare a DOCTYPE (KSE files have none)";

	@TempDir
	Path directory;

	@Test
	void aModelWithSixtyThousandGuardsFullOfEntitiesIsSavedAndOpensAgainBothWays() throws IOException {
		StatechartFactory factory = StatechartFactory.eINSTANCE;
		Model model = factory.createModel();
		model.setName("Crowd");
		Node root = factory.createNode();
		root.setName("Crowd");
		root.setType("OR");
		model.getNodes().add(root);
		List<Node> states = new ArrayList<>();
		for (int i = 0; i < 2_000; i++) {
			Node state = factory.createNode();
			state.setName("S" + i);
			state.setType("BASIC");
			state.setLabel("0." + i);
			root.getChildren().add(state);
			states.add(state);
		}
		for (int i = 0; i < 60_000; i++) {
			Transition transition = factory.createTransition();
			transition.setSource(states.get(i % states.size()));
			transition.setTarget(states.get((i * 7 + 1) % states.size()));
			// four &amp; and two &quot; (counted twice by the parser) a transition: 480,000 in all
			transition.setTE("[a.b.C.ok()==1 && w.x.Y.name()==\"go" + i + "\" && t.u.V.n()>2]/k.A.B.c()");
			model.getTransitions().add(transition);
		}
		Model expected = EcoreUtil.copy(model);
		Path file = directory.resolve("Crowd.stct");
		StatechartResources.save(model, file);
		String text = Files.readString(file, StandardCharsets.US_ASCII);
		assertTrue(count(text, "&amp;") == 240_000 && count(text, "&quot;") == 120_000, "the guards are saved with their entities");

		long start = System.nanoTime();
		Model streamed = StatechartResources.load(file, true);
		long streaming = System.nanoTime() - start;
		start = System.nanoTime();
		Model emf = StatechartResources.load(file, false);
		long parsed = System.nanoTime() - start;
		System.out.printf("[ entities ] %,d bytes, 360,000 entity references: streaming reader %d ms, EMF's parser %d ms%n", text.length(),
				streaming / 1_000_000, parsed / 1_000_000);

		assertTrue(StatechartResources.streamed(streamed.eResource()), () -> "left to EMF: " + StatechartResources.fallbackReason(streamed.eResource()));
		assertTrue(EcoreUtil.equals(expected, streamed), "the streaming reader gives the model saved");
		assertTrue(EcoreUtil.equals(expected, emf), "EMF's parser gives the model saved");
		assertEquals("[a.b.C.ok()==1 && w.x.Y.name()==\"go59999\" && t.u.V.n()>2]/k.A.B.c()", emf.getTransitions().get(59_999).getTE());
	}

	/**
	 * A DOCTYPE with an internal subset, with an external DTD on a server, with an entity that a
	 * value uses: all refused by both readers with the same message, at the DOCTYPE's line, before
	 * anything is fetched.
	 */
	@Test
	void aDoctypeIsRefusedWithTheSameMessageBothWaysAndNothingIsFetched() throws IOException {
		try (NetworkTrap trap = new NetworkTrap()) {
			String remote = trap.remote();
			List<String> doctypes = List.of("<!DOCTYPE statechart:Model [<!ENTITY name \"expanded\">]>",
					"<!DOCTYPE x SYSTEM \"" + remote + "/model.dtd\">",
					"<!DOCTYPE x PUBLIC \"-//KSE//x//EN\" \"" + remote + "/public.dtd\">",
					"<!DOCTYPE x [<!ENTITY % p SYSTEM \"" + remote + "/p.dtd\"> %p;]>",
					"<!DOCTYPE x [<!ENTITY e SYSTEM \"" + remote + "/e\">]>");
			int i = 0;
			for (String doctype : doctypes) {
				String value = doctype.contains("ENTITY name") ? "&name;" : doctype.contains("ENTITY e ") ? "&e;" : "plain";
				for (String text : List.of(HEADER + doctype + "\n" + ROOT + " name=\"" + value + "\"/>\n",
						HEADER + "<!-- shared -->\n\n" + doctype + "\n" + ROOT + " name=\"" + value + "\"/>\n", doctype + ROOT + " name=\"" + value + "\"/>\n")) {
					Path file = directory.resolve("Doctype" + i++ + ".stct");
					Files.writeString(file, text, StandardCharsets.US_ASCII);
					int line = (int) text.substring(0, text.indexOf("<!DOCTYPE")).chars().filter(c -> c == '\n').count() + 1;
					IOException streamed = assertThrows(IOException.class, () -> StatechartResources.load(file, true), text);
					IOException parsed = assertThrows(IOException.class, () -> StatechartResources.load(file, false), text);
					assertEquals(parsed.getMessage(), streamed.getMessage(), text);
					assertTrue(streamed.getMessage().matches(java.util.regex.Pattern.quote(file + ":" + line + ":") + "\\d+" + java.util.regex.Pattern.quote(REFUSED)),
							streamed.getMessage());
					assertNull(trap.take(), text);
				}
			}
		}
	}

	/** The line and column are where the parser stops, just after the word DOCTYPE, as an editor counts them. */
	@Test
	void theRefusalNamesTheDoctypesLineAndColumn() throws IOException {
		Path file = directory.resolve("Goalie.stct");
		Files.writeString(file, HEADER + "<!DOCTYPE m [<!ENTITY e \"x\">]>\n" + ROOT + " name=\"&e;\"/>\n", StandardCharsets.US_ASCII);
		IOException refused = assertThrows(IOException.class, () -> StatechartResources.load(file));
		assertEquals(file + ":2:10" + REFUSED, refused.getMessage());
	}

	/** Ten levels of ten entities each would be 10^9 copies of "lol": refused at the DOCTYPE, at once. */
	@Test
	void aBillionLaughsIsRefusedAtOnce() throws IOException {
		StringBuilder doctype = new StringBuilder("<!DOCTYPE statechart:Model [\n  <!ENTITY lol0 \"lol\">\n");
		for (int level = 1; level <= 10; level++) {
			doctype.append("  <!ENTITY lol").append(level).append(" \"").append(("&lol" + (level - 1) + ";").repeat(10)).append("\">\n");
		}
		doctype.append("]>\n");
		Path file = directory.resolve("Laughs.stct");
		Files.writeString(file, HEADER + doctype + ROOT + " name=\"&lol10;\"/>\n", StandardCharsets.US_ASCII);
		for (boolean streaming : new boolean[] { true, false }) {
			long start = System.nanoTime();
			IOException refused = assertTimeoutPreemptively(Duration.ofSeconds(5),
					() -> assertThrows(IOException.class, () -> StatechartResources.load(file, streaming)));
			long millis = (System.nanoTime() - start) / 1_000_000;
			assertEquals(file + ":2:10" + REFUSED, refused.getMessage());
			assertTrue(millis < 1_000, "refused in " + millis + " ms");
		}
	}

	private static int count(String text, String part) {
		int count = 0;
		for (int at = text.indexOf(part); at >= 0; at = text.indexOf(part, at + part.length())) {
			count++;
		}
		return count;
	}
}
