package org.kse.model.tests;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.eclipse.emf.ecore.util.EcoreUtil;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.labeling.Labeler;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.StatechartFactory;
import org.kse.model.statechart.Variable;

/**
 * Issue 13: everything KSE writes it reads back. Seeded random models, of every shape and with
 * text of every kind a user can type or paste (quotes, markup, line breaks, tabs, leading spaces,
 * Greek, emoji), are saved, loaded and saved again: the model that comes back equals the one
 * written, and the second file is the same bytes. Text a file cannot hold is refused at save.
 */
class WrittenModelsReadBackTest {

	private static final long SEED = Long.parseLong(System.getenv().getOrDefault("KSE_FUZZ_SEED", "20261123"));
	private static final String[] KINDS = { "OR", "AND", "BASIC", "START", "END", "CONDITION" };
	private static final String[] PIECES = { "a", "Scan", "0.1", " ", "  lead", "trail  ", "\"", "'", "<", ">", "&", "&amp;", "]]>", "\n", "\r\n",
			"\t", "\u00e9", "\u03a3\u03b1", "\ud83e\udd16", "\\", "/", "#", "//@nodes.0", "[a.b.C.d()==1]", "/TimeoutAction.behavior.250", "%20", "${x}",
			"\u00a0", "\ufeff", "\ufffd" };

	@TempDir
	Path directory;

	@Test
	void everyModelKseWritesLoadsAsItWasWritten() throws IOException {
		Random random = new Random(SEED);
		for (int i = 0; i < 300; i++) {
			Model model = randomModel(random);
			if (random.nextBoolean()) {
				Labeler.label(model);
			}
			Path file = directory.resolve("M" + i + ".stct");
			Model copy = EcoreUtil.copy(model);
			StatechartResources.save(model, file);
			byte[] written = Files.readAllBytes(file);
			Model loaded = StatechartResources.load(file);
			int index = i;
			assertTrue(EcoreUtil.equals(copy, loaded), () -> "seed " + SEED + ", model " + index + " changed on the way:\n" + new String(written));
			Path again = directory.resolve("again.stct");
			StatechartResources.save(loaded, again);
			assertArrayEquals(written, Files.readAllBytes(again), "seed " + SEED + ", model " + i + ": saving what was loaded gives other bytes");
		}
		System.out.println("[ round trip ] 300 random models written and read back, seed " + SEED);
	}

	@Test
	void textThatAFileCannotHoldIsRefusedNamingItsElementAndTheFileIsKept() throws IOException {
		Random random = new Random(SEED);
		Path file = directory.resolve("M.stct");
		for (String bad : List.of("\u0000", "\u0001", "\u001f", "\ud800", "\udfff", "\ufffe", "\uffff")) {
			Model model = randomModel(random);
			StatechartResources.save(model, file);
			byte[] before = Files.readAllBytes(file);
			Node state = model.getNodes().get(0);
			state.setName("Scan" + bad + "Ball");
			IOException refused = assertThrows(IOException.class, () -> StatechartResources.save(model, file));
			assertTrue(refused.getMessage().startsWith("cannot save: the name of state "), refused.getMessage());
			assertTrue(refused.getMessage().endsWith(" at position 5, which a model file cannot hold"), refused.getMessage());
			assertArrayEquals(before, Files.readAllBytes(file), "the file on disk is left as it was");
		}
	}

	static Model randomModel(Random random) {
		StatechartFactory factory = StatechartFactory.eINSTANCE;
		Model model = factory.createModel();
		model.setName(text(random));
		List<Node> all = new ArrayList<>();
		Node root = node(random, "OR");
		model.getNodes().add(root);
		all.add(root);
		int count = 1 + random.nextInt(40);
		for (int i = 0; i < count; i++) {
			Node parent = all.get(random.nextInt(all.size()));
			Node child = node(random, KINDS[random.nextInt(KINDS.length)]);
			parent.getChildren().add(child);
			all.add(child);
		}
		for (int i = random.nextInt(3); i > 0; i--) {
			Variable variable = factory.createVariable();
			variable.setName(text(random));
			variable.setType(random.nextBoolean() ? "worldstate.State.GameStateMessage" : text(random));
			model.getVariables().add(variable);
			all.get(random.nextInt(all.size())).getVariables().add(variable);
		}
		for (int i = random.nextInt(2 * all.size()); i > 0; i--) {
			var transition = factory.createTransition();
			transition.setSource(all.get(random.nextInt(all.size())));
			transition.setTarget(all.get(random.nextInt(all.size())));
			if (random.nextInt(4) > 0) {
				transition.setTE(text(random));
			}
			if (random.nextBoolean()) {
				transition.setName(text(random));
			}
			model.getTransitions().add(transition);
		}
		return model;
	}

	private static Node node(Random random, String kind) {
		Node node = StatechartFactory.eINSTANCE.createNode();
		node.setType(random.nextInt(20) == 0 ? text(random) : kind);
		node.setName(random.nextInt(10) == 0 ? null : text(random));
		node.setLabel(random.nextInt(5) == 0 ? null : text(random));
		return node;
	}

	private static String text(Random random) {
		StringBuilder text = new StringBuilder();
		for (int i = random.nextInt(5); i >= 0; i--) {
			text.append(PIECES[random.nextInt(PIECES.length)]);
		}
		return text.toString();
	}
}
