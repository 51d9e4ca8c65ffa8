package org.kse.labeling.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.testing.Models;
import org.kse.labeling.Copies;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.model.statechart.Variable;
import org.kse.validation.ModelValidation;

/** Copy and paste of states: children, inner transitions and variables come along, labels stay unique and ordered. */
class CopiesTest {

	private static Model goalie() throws IOException {
		return StatechartResources.load(Path.of(System.getProperty("kse.examples"), "Goalie", "Goalie.stct"));
	}

	private static void add(Model model, Copies.Pasted pasted) {
		model.getVariables().addAll(pasted.variables());
		model.getTransitions().addAll(pasted.transitions());
		if (pasted.container() instanceof Node parent) {
			parent.getChildren().addAll(pasted.states());
		} else {
			model.getNodes().addAll(pasted.states());
		}
	}

	private static List<String> labels(Model model) {
		return Models.allNodes(model).stream().map(Node::getLabel).toList();
	}

	@Test
	void aCompositePastedElsewhereIsRelabelledBelowItsNewParent(@TempDir Path directory) throws IOException {
		Model model = goalie();
		Node followBall = Models.byLabel(model, "0.2.2.3.6");
		Node nonPlaying = Models.byLabel(model, "0.2.2.4");
		long inner = model.getTransitions().stream()
				.filter(t -> Models.isInside(t.getSource(), followBall) && Models.isInside(t.getTarget(), followBall)).count();
		List<String> before = labels(model);

		Copies.Fragment copied = Copies.copy(model, List.of(followBall, Models.byLabel(model, "0.2.2.3.6.2")));
		assertEquals(1, copied.states().size(), "a state inside a copied one goes with it, once");
		Copies.Pasted pasted = Copies.prepare(copied, model, nonPlaying);
		add(model, pasted);

		Node copy = pasted.states().get(0);
		assertEquals("0.2.2.4.5", copy.getLabel(), "after nonPlaying's four children");
		assertEquals("followBall", copy.getName(), "a named state keeps its name");
		assertEquals("0.2.2.4.5.2.2", Models.byLabel(model, "0.2.2.4.5.2.2").getLabel());
		assertEquals("Stare", Models.byLabel(model, "0.2.2.4.5.2.2").getName(), "the insides in their old order");
		assertEquals("0.2.2.4.5.1", Models.byLabel(model, "0.2.2.4.5.1").getName(), "auxiliary states are named by their new label");
		assertEquals(inner, pasted.transitions().size(), "the transitions inside come along");
		for (Transition transition : pasted.transitions()) {
			assertTrue(Models.isInside(transition.getSource(), copy) && Models.isInside(transition.getTarget(), copy), transition.getName());
		}
		assertTrue(pasted.transitions().stream().anyMatch(t -> t.getName().equals("0.2.2.4.5.1_TO_Stare_one_or_more_times_")),
				"transitions named after their states are renamed");
		List<String> after = labels(model);
		assertEquals(after.size(), new HashSet<>(after).size(), "labels stay unique");
		assertTrue(after.containsAll(before), "the original states keep their labels");
		assertEquals(0, ModelValidation.validate(model).getChildren().stream().filter(d -> d.getSeverity() == org.eclipse.emf.common.util.Diagnostic.ERROR)
				.count(), "the model stays valid");

		Copies.Pasted again = Copies.prepare(copied, model, nonPlaying);
		add(model, again);
		assertEquals("0.2.2.4.6", again.states().get(0).getLabel(), "a second paste takes the next label");
		assertNotSame(copy, again.states().get(0));

		Path file = directory.resolve("Goalie.stct");
		StatechartResources.save(model, file);
		String saved = Files.readString(file);
		assertTrue(saved.contains("label=\"0.2.2.4.5.2.2\"") && saved.contains("label=\"0.2.2.4.6.2.2\""), "the labels are saved");
		assertEquals(after.size() + Models.allNodes(copy).size() + 1, Models.allNodes(StatechartResources.load(file)).size());
	}

	@Test
	void variablesComeAlongAndAreSharedWhenTheModelHasThemAlready() throws IOException {
		Model model = goalie();
		Variable ball = Models.FACTORY.createVariable();
		ball.setName("ball");
		ball.setType("worldstate.Data.WorldInfo");
		model.getVariables().add(ball);
		Node kick = Models.byLabel(model, "0.2.2.3.5");
		kick.getVariables().add(ball);

		Copies.Pasted sameModel = Copies.prepare(Copies.copy(model, List.of(kick)), model, Models.byLabel(model, "0.2.2.4"));
		assertEquals(List.of(), sameModel.variables(), "the model has the variable: no copy");
		assertEquals(List.of(ball), sameModel.states().get(0).getVariables());

		Model other = goalie();
		Variable clash = Models.FACTORY.createVariable();
		clash.setName("ball");
		clash.setType("behavior.State.Other");
		other.getVariables().add(clash);
		Copies.Pasted otherModel = Copies.prepare(Copies.copy(model, List.of(kick)), other, other.getNodes().get(0));
		assertEquals(1, otherModel.variables().size(), "the variable is brought into the other model");
		assertEquals("ball_2", otherModel.variables().get(0).getName(), "renamed: 'ball' is another message there");
		assertEquals(otherModel.variables(), otherModel.states().get(0).getVariables());
		assertEquals("0.4", otherModel.states().get(0).getLabel(), "after the root's children");
	}
}
