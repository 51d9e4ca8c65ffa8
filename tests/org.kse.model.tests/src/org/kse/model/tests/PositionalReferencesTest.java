package org.kse.model.tests;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.emf.ecore.xmi.XMLResource;
import org.eclipse.emf.ecore.xmi.impl.XMIResourceImpl;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.StatechartFactory;
import org.kse.model.statechart.Transition;
import org.kse.testing.Models;

/**
 * Issue 17 (item 3): KSE writes and reads the original tool's positional references
 * ({@code //@nodes.0/@Children.3}) without EMF's search from the root for each one. What it
 * writes and what it reads must stay exactly EMF's: the same bytes as a plain EMF XMI resource
 * writes with the same options, and every reference read to the element a plain EMF resource
 * finds.
 */
class PositionalReferencesTest {

	@TempDir
	Path directory;

	/** The legacy models, random models of every shape, and a wide and deep one. */
	private static List<Model> models() throws IOException {
		List<Model> models = new ArrayList<>();
		for (Path legacy : Models.legacyModels()) {
			models.add(StatechartResources.load(legacy));
		}
		Random random = new Random(17);
		for (int i = 0; i < 100; i++) {
			models.add(WrittenModelsReadBackTest.randomModel(random));
		}
		Model wide = wideAndDeep();
		models.add(wide);
		assertTrue(new String(StatechartResources.toBytes(EcoreUtil.copy(wide))).contains("target=\"//@nodes.0/@Children.0/@Children.0"),
				"the wide and deep model is written with positional references");
		return models;
	}

	@Test
	void kseWritesTheBytesEmfWrites() throws IOException {
		for (Model model : models()) {
			byte[] ours = StatechartResources.toBytes(EcoreUtil.copy(model));
			assertArrayEquals(plainEmf(EcoreUtil.copy(model)), ours, () -> model.getName() + ":\n" + new String(ours));
		}
	}

	@Test
	void kseReadsEveryReferenceAsEmfDoes() throws IOException {
		int i = 0;
		for (Model model : models()) {
			Path file = directory.resolve("m" + i++ + ".stct");
			StatechartResources.save(EcoreUtil.copy(model), file);
			Model ours = StatechartResources.load(file);
			Resource plain = new XMIResourceImpl(URI.createFileURI(file.toString()));
			plain.load(Map.of(XMLResource.OPTION_DEFER_IDREF_RESOLUTION, Boolean.TRUE));
			Model theirs = (Model) plain.getContents().get(0);
			assertTrue(EcoreUtil.equals(theirs, ours), file::toString);
			assertEquals(fragments(theirs), fragments(ours), file.toString());
		}
	}

	/** Where every reference of the model leads, as paths of the model. */
	private static List<String> fragments(Model model) {
		List<String> fragments = new ArrayList<>();
		for (Transition transition : model.getTransitions()) {
			fragments.add(path(transition.getSource()) + " -> " + path(transition.getTarget()));
		}
		for (var it = model.eAllContents(); it.hasNext();) {
			if (it.next() instanceof Node node) {
				node.getVariables().forEach(variable -> fragments.add(path(node) + " reads " + path(variable)));
			}
		}
		return fragments;
	}

	/** Computed by EMF in a resource set of its own, so that KSE's resource plays no part. */
	private static String path(EObject element) {
		return element == null ? "null" : element.eIsProxy() ? "proxy " + EcoreUtil.getURI(element) : EcoreUtil.getRelativeURIFragmentPath(null, element);
	}

	private static byte[] plainEmf(Model model) throws IOException {
		Resource resource = new XMIResourceImpl(URI.createFileURI("model.stct"));
		resource.getContents().add(model);
		ByteArrayOutputStream bytes = new ByteArrayOutputStream();
		// StatechartResources' save options
		resource.save(bytes, Map.of(XMLResource.OPTION_ENCODING, "ASCII", XMLResource.OPTION_SAVE_TYPE_INFORMATION, Boolean.FALSE,
				XMLResource.OPTION_SKIP_ESCAPE_URI, Boolean.FALSE));
		return bytes.toByteArray();
	}

	/** 40 composites of 60 states each, nested 30 deep in one branch, transitions across every list. */
	private static Model wideAndDeep() {
		StatechartFactory factory = StatechartFactory.eINSTANCE;
		Model model = factory.createModel();
		model.setName("WideAndDeep");
		Node root = state(factory, "root", "OR");
		model.getNodes().add(root);
		Node deep = root;
		for (int level = 0; level < 30; level++) {
			Node next = state(factory, "deep" + level, "OR");
			deep.getChildren().add(next);
			deep = next;
		}
		for (int c = 0; c < 40; c++) {
			Node composite = state(factory, "c" + c, "OR");
			(c % 2 == 0 ? root : deep).getChildren().add(composite);
			Node previous = null;
			for (int s = 0; s < 60; s++) {
				Node state = state(factory, "s" + c + "_" + s, "BASIC");
				composite.getChildren().add(state);
				if (previous != null) {
					Transition transition = factory.createTransition();
					transition.setSource(previous);
					transition.setTarget(state);
					model.getTransitions().add(transition);
				}
				previous = state;
			}
		}
		return model;
	}

	private static Node state(StatechartFactory factory, String name, String type) {
		Node node = factory.createNode();
		node.setName(name);
		node.setType(type);
		return node;
	}
}
