package org.kse.model.tests;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.InternalEObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.emf.ecore.xmi.XMLResource;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.kse.labeling.Labeler;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.StatechartFactory;
import org.kse.model.statechart.Transition;
import org.kse.model.statechart.Variable;
import org.kse.testing.ByteMutator;

/**
 * Issue 17 (item 3), ADR 0026: the streaming reader and writer of {@code .stct} files give what
 * EMF's XMI parser and serializer give. Every model file of the project, seeded random models and
 * mutants of the project's files are read both ways: the same model with the same URI fragments,
 * or the same refusal word for word; every model is written both ways to the same bytes. The files
 * KSE writes must go the streaming way (else the speed is lost without a test noticing), and what
 * the streaming reader does not know must go EMF's way.
 */
class StreamingModelIoTest {

	private static final Path REPOSITORY = Path.of(System.getProperty("kse.repository", "../.."));
	private static final long SEED = Long.parseLong(System.getenv().getOrDefault("KSE_FUZZ_SEED", "20261126"));
	private static final String HEADER = "<?xml version=\"1.0\" encoding=\"ASCII\"?>\n";
	private static final String ROOT = "<statechart:Model xmi:version=\"2.0\" xmlns:xmi=\"http://www.omg.org/XMI\" xmlns:statechart=\"http://statechart/1.0\"";

	@TempDir
	Path directory;

	/** Every model file of the project: legacy, hostile, examples, generator and conformance models. */
	static List<Path> projectFiles() throws IOException {
		List<Path> files = new ArrayList<>();
		for (Path top : List.of(REPOSITORY.resolve("tests"), REPOSITORY.resolve("examples"))) {
			try (Stream<Path> walk = Files.walk(top)) {
				walk.filter(path -> path.toString().endsWith(".stct") && !path.toString().contains("/target/") && !path.toString().contains("/node_modules/"))
						.sorted().forEach(files::add);
			}
		}
		assertTrue(files.size() > 50, "the project's model files are found under " + REPOSITORY.toAbsolutePath());
		assertTrue(files.stream().anyMatch(path -> path.endsWith("legacy-kse/Goalie/Goalie.stct")), "the legacy files are among them");
		assertTrue(files.stream().anyMatch(path -> path.endsWith("hostile/Hostile.stct")), "the hostile file is among them");
		return files;
	}

	@ParameterizedTest(name = "{0}")
	@MethodSource("projectFiles")
	void everyModelFileOfTheProjectIsStreamedToWhatEmfReads(Path file) throws IOException {
		Model ours = StatechartResources.load(file);
		Model emf = StatechartResources.load(file, false);
		assertTrue(StatechartResources.streamed(ours.eResource()), () -> file + " was left to EMF: " + StatechartResources.fallbackReason(ours.eResource()));
		assertFalse(StatechartResources.streamed(emf.eResource()), "load(file, false) is EMF's");
		assertSameModel(emf, ours, file.toString());
		assertEquals(((XMLResource) emf.eResource()).getEncoding(), ((XMLResource) ours.eResource()).getEncoding(), "the encoding recorded on the resource");

		byte[] written = StatechartResources.toBytes(ours);
		assertTrue(StatechartResources.streamed(ours.eResource()), () -> file + " was saved by EMF: " + StatechartResources.fallbackReason(ours.eResource()));
		assertArrayEquals(StatechartResources.toBytes(emf, false), written, file + ": the streaming writer writes other bytes than EMF");
	}

	@Test
	void randomModelsAreWrittenAndReadAsEmfDoes() throws IOException {
		Random random = new Random(SEED);
		int streamed = 0;
		for (int i = 0; i < 300; i++) {
			Model model = i % 10 == 9 ? deep(random, 50 + random.nextInt(40)) : WrittenModelsReadBackTest.randomModel(random);
			if (random.nextBoolean()) {
				Labeler.label(model);
			}
			String what = "seed " + SEED + ", model " + i;
			byte[] emf = StatechartResources.toBytes(EcoreUtil.copy(model), false);
			Model copy = EcoreUtil.copy(model);
			byte[] ours = StatechartResources.toBytes(copy);
			assertArrayEquals(emf, ours, () -> what + ": the streaming writer writes other bytes than EMF:\n" + new String(ours, StandardCharsets.US_ASCII));

			Path file = directory.resolve("M" + i + ".stct");
			Files.write(file, emf);
			Model read = StatechartResources.load(file);
			if (StatechartResources.streamed(read.eResource())) {
				streamed++;
			}
			assertSameModel(StatechartResources.load(file, false), read, what);
			assertTrue(EcoreUtil.equals(model, read), what + ": the model read is not the model written");
		}
		assertEquals(300, streamed, "every model KSE writes is read back by the streaming reader");
	}

	/** A chain of composite states {@code levels} deep, transitions between the levels, variables read on the way. */
	private static Model deep(Random random, int levels) {
		StatechartFactory factory = StatechartFactory.eINSTANCE;
		Model model = factory.createModel();
		model.setName("Deep" + levels);
		Variable variable = factory.createVariable();
		variable.setName("ball");
		variable.setType("");
		model.getVariables().add(variable);
		Node parent = factory.createNode();
		parent.setName("root");
		model.getNodes().add(parent);
		List<Node> states = new ArrayList<>(List.of(parent));
		for (int level = 0; level < levels; level++) {
			Node child = factory.createNode();
			child.setName("level " + level + " \u00e9\u20ac\ud83e\udd16");
			child.setType(level % 2 == 0 ? "OR" : "");
			if (random.nextBoolean()) {
				child.getVariables().add(variable);
			}
			parent.getChildren().add(child);
			Node sibling = factory.createNode();
			parent.getChildren().add(sibling);
			states.add(child);
			states.add(sibling);
			parent = child;
		}
		for (int i = 0; i < 3 * levels; i++) {
			Transition transition = factory.createTransition();
			transition.setSource(states.get(random.nextInt(states.size())));
			transition.setTarget(random.nextInt(10) == 0 ? null : states.get(random.nextInt(states.size())));
			transition.setTE(random.nextBoolean() ? "[a.b==\"x\"] & <tab>\t" : null);
			model.getTransitions().add(transition);
		}
		return model;
	}

	/**
	 * Mutants of the project's files (bytes flipped, cut, repeated, words that break XML put in):
	 * each is read to the same model both ways, or refused by both with the same message. Both
	 * outcomes must occur, and the streaming reader must take some of the mutants it can read.
	 */
	@Test
	void mutantsOfTheProjectsFilesAreReadOrRefusedAsEmfDoes() throws IOException {
		List<Path> seeds = projectFiles().stream().filter(path -> {
			try {
				return Files.size(path) < 40_000;
			} catch (IOException e) {
				throw new java.io.UncheckedIOException(e);
			}
		}).toList();
		List<String> words = List.of("<", ">", "&", "&amp;", "&quot;", "&#x0;", "&#1;", "&#x10FFFF;", "&#xD800;",
				"&#X41;", "&#65;", "&bogus;", "\"", "'", " ", "\t", "\r\n", "=", "/", "<!--", "-->", "--", "<!DOCTYPE x [<!ENTITY e \"x\">]>", "&e;",
				"<![CDATA[x]]>", "<?pi x?>", " xmlns:a=\"b\"", " xsi:type=\"statechart:Node\"", " xmi:id=\"n1\"", " href=\"other.stct#//@nodes.0\"",
				"//@nodes.0", "/@Children.", ".0", "00", "9", "-1", " ", "\u00e9", "encoding=\"UTF-8\"", "encoding=\"ISO-8859-1\"", " name=\"a\"",
				" Father_of=\"//@nodes.0\"", " variables=\"//@variables.0\"", "<Children/>", "</Children>", "<nodes>", "</nodes>", "<variables name=\"v\"/>",
				"<transitions source=\"//@nodes.0\" target=\"//@variables.0\"/>", "<statechart:Model>", "xmi:version=\"2.1\"");
		Random random = new Random(SEED);
		ByteMutator mutator = new ByteMutator(random, words);
		int both = 0;
		int refused = 0;
		int streamed = 0;
		for (int i = 0; i < 1500; i++) {
			Path seed = seeds.get(i % seeds.size());
			Path mutant = directory.resolve("mutant" + i + ".stct");
			// half of them hostile, half one small edit away from the original (which mostly still reads)
			Files.write(mutant, i % 2 == 0 ? mutator.mutate(Files.readAllBytes(seed)) : edit(random, Files.readString(seed, StandardCharsets.ISO_8859_1), words));
			String what = "mutant " + i + " of " + seed.getFileName() + " (seed " + SEED + ")";
			Outcome ours = Outcome.of(mutant, true);
			Outcome emf = Outcome.of(mutant, false);
			assertEquals(emf.message, ours.message, what + ": refused otherwise");
			if (ours.model != null) {
				both++;
				assertSameModel(emf.model, ours.model, what);
				if (StatechartResources.streamed(ours.model.eResource())) {
					streamed++;
				}
			} else {
				refused++;
			}
		}
		System.out.println("[ streaming ] 1500 mutants: " + both + " read alike (" + streamed + " by the streaming reader), " + refused + " refused alike, seed " + SEED);
		assertTrue(refused > 100 && both > 100 && streamed > 50, "mutants read " + both + " (streamed " + streamed + "), refused " + refused);
	}

	/** One word put in, one character replaced, or a few taken out. */
	private static byte[] edit(Random random, String text, List<String> words) {
		int at = random.nextInt(text.length());
		String edited = switch (random.nextInt(3)) {
		case 0 -> text.substring(0, at) + words.get(random.nextInt(words.size())) + text.substring(at);
		case 1 -> text.substring(0, at) + (char) (0x20 + random.nextInt(0x5F)) + text.substring(at + 1);
		default -> text.substring(0, at) + text.substring(Math.min(text.length(), at + 1 + random.nextInt(3)));
		};
		return edited.getBytes(StandardCharsets.ISO_8859_1);
	}

	/** Files outside KSE's dialect: EMF reads or refuses them, and says the same as before. */
	@Test
	void whatTheStreamingReaderDoesNotKnowIsLeftToEmf() throws IOException {
		String node = "  <nodes name=\"a\" type=\"OR\">\n    <Children name=\"b\"/>\n  </nodes>\n";
		String end = "</statechart:Model>\n";
		List<String> files = List.of(
				// read by EMF to a model
				"<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?>\n" + ROOT + " name=\"caf\u00e9\">\n" + node + end,
				HEADER + ROOT + " xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\">\n  <nodes xsi:type=\"statechart:Node\" name=\"a\"/>\n" + end,
				HEADER + ROOT + ">\n" + node + "  <transitions source=\"other.stct#//@nodes.0\" target=\"//@nodes.0\"/>\n" + end,
				HEADER + ROOT + ">\n" + node + "  <transitions target=\"//@nodes.0\">\n    <source href=\"other.stct#//@nodes.0\"/>\n  </transitions>\n" + end,
				HEADER + ROOT + ">\n" + node + "  <transitions source=\"//@nodes.0/@Children.00\"/>\n" + end,
				HEADER + ROOT + ">\n" + node + "  <transitions source=\"  //@nodes.0\"/>\n" + end,
				HEADER + ROOT + " name=\"line&#10;break\tand tab\">\n" + node + end,
				HEADER + "<?pi here?>\n" + ROOT + "/>\n",
				"\ufeff" + HEADER + ROOT + "/>\n",
				HEADER + "<xmi:XMI xmi:version=\"2.0\" xmlns:xmi=\"http://www.omg.org/XMI\" xmlns:statechart=\"http://statechart/1.0\">\n  <statechart:Model name=\"one\"/>\n  <statechart:Model name=\"two\"/>\n</xmi:XMI>\n",
				// refused by EMF
				HEADER + "<!DOCTYPE statechart:Model [<!ENTITY name \"expanded\">]>\n" + ROOT + " name=\"&name;\"/>\n",
				HEADER + ROOT + " name=\"&bogus;\"/>\n",
				HEADER + ROOT + " name=\"a\" name=\"b\"/>\n",
				HEADER + ROOT + ">\n  <nodes name=\"a\" colour=\"red\"/>\n" + end,
				HEADER + ROOT + ">\n  <states name=\"a\"/>\n" + end,
				HEADER + ROOT + ">\n" + node + "  <transitions source=\"//@nodes.0/@Children.7\"/>\n" + end,
				HEADER + ROOT + ">\n" + node + "  <variables name=\"v\"/>\n  <transitions source=\"//@variables.0\"/>\n" + end,
				HEADER + ROOT + ">\n" + node + "  <transitions source=\"//@nodes.0 //@nodes.0/@Children.0\"/>\n" + end,
				HEADER + ROOT + ">\n  <nodes name=\"a\">\n" + end,
				HEADER + ROOT + ">\n  <nodes name=\"a\">text</nodes>\n" + end,
				HEADER + ROOT + " name=\"&#x1;\"/>\n",
				HEADER + ROOT + " name=\"a\"/>\n<nodes/>\n",
				"<?xml version=\"1.1\" encoding=\"ASCII\"?>\n" + ROOT + "/>\n",
				HEADER + "<statechart:Model xmlns:statechart=\"http://statechart/2.0\"/>\n");
		int i = 0;
		for (String text : files) {
			Path file = directory.resolve("other" + i++ + ".stct");
			Files.write(file, text.getBytes(text.contains("ISO-8859-1") ? StandardCharsets.ISO_8859_1 : StandardCharsets.UTF_8));
			Outcome ours = Outcome.of(file, true);
			Outcome emf = Outcome.of(file, false);
			assertEquals(emf.message, ours.message, text);
			if (ours.model != null) {
				assertFalse(StatechartResources.streamed(ours.model.eResource()), () -> "streamed, though not KSE's dialect:\n" + text);
				assertNotNull(StatechartResources.fallbackReason(ours.model.eResource()));
				assertSameModel(emf.model, ours.model, text);
			}
		}
	}

	/**
	 * The JDK's parser refuses a document with more than 100,000 predefined entities (counting
	 * {@code &quot;} twice) and one nested deeper than its limit. KSE's loads lift the entity limits
	 * (a model file has no DOCTYPE, so they only count the predefined ones) and raise the depth; the
	 * streaming reader follows the limits a load sets, and leaves files at them to the parser, so
	 * that they are read or refused as EMF reads or refuses them.
	 */
	@Test
	void theParsersLimitsStayTheParsers() throws IOException {
		StatechartFactory factory = StatechartFactory.eINSTANCE;
		// six entities a state: &amp;&amp;&lt;&lt;&quot;
		for (int states : new int[] { 8_332, 8_334, 16_665, 16_667 }) {
			Model model = factory.createModel();
			Node root = factory.createNode();
			model.getNodes().add(root);
			for (int i = 0; i < states; i++) {
				Node state = factory.createNode();
				state.setName("&&<<\"" + i);
				root.getChildren().add(state);
			}
			Path file = directory.resolve("entities" + states + ".stct");
			Files.write(file, StatechartResources.toBytes(model));
			// KSE's own load options: no entity limit, whatever the JDK's
			Outcome ours = Outcome.of(file, true);
			Outcome emf = Outcome.of(file, false);
			assertTrue(StatechartResources.streamed(ours.model.eResource()), StatechartResources.fallbackReason(ours.model.eResource()));
			assertSameModel(emf.model, ours.model, states + " states");
			// a load that sets the JDK 25 default, or a lower total
			for (Map<String, String> limits : List.of(Map.of("jdk.xml.maxGeneralEntitySizeLimit", "100000"),
					Map.of("jdk.xml.maxGeneralEntitySizeLimit", "0", "jdk.xml.totalEntitySizeLimit", "50000"))) {
				int limit = limits.containsKey("jdk.xml.totalEntitySizeLimit") ? 50_000 : 100_000;
				Outcome limited = Outcome.of(file, true, limits);
				Outcome limitedEmf = Outcome.of(file, false, limits);
				assertEquals(limitedEmf.message, limited.message, states + " states, " + limits);
				if (6 * states < limit) {
					assertTrue(StatechartResources.streamed(limited.model.eResource()), StatechartResources.fallbackReason(limited.model.eResource()));
					assertSameModel(limitedEmf.model, limited.model, states + " states, " + limits);
				} else {
					assertTrue(limited.message.contains("\"" + String.format(java.util.Locale.ROOT, "%,d", limit) + "\" limit"), limited.message);
				}
			}
		}
		// the root is at depth 1, its states at 2: the deepest state of a chain of n is at n + 1
		for (int depth : new int[] { StatechartResources.MAX_ELEMENT_DEPTH - 1, StatechartResources.MAX_ELEMENT_DEPTH,
				StatechartResources.MAX_ELEMENT_DEPTH + 1 }) {
			StringBuilder text = new StringBuilder(HEADER).append(ROOT).append(">\n<nodes name=\"0\">");
			text.append("<Children>".repeat(depth - 2)).append("</Children>".repeat(depth - 2)).append("</nodes>\n</statechart:Model>\n");
			Path file = directory.resolve("depth" + depth + ".stct");
			Files.writeString(file, text, StandardCharsets.US_ASCII);
			Outcome ours = Outcome.of(file, true);
			Outcome emf = Outcome.of(file, false);
			assertEquals(emf.message, ours.message, "depth " + depth);
			if (depth <= StatechartResources.MAX_ELEMENT_DEPTH) {
				assertEquals(depth == StatechartResources.MAX_ELEMENT_DEPTH - 1, StatechartResources.streamed(ours.model.eResource()),
						"depth " + depth + ": " + StatechartResources.fallbackReason(ours.model.eResource()));
				// paths of 10,000 segments are too long to list: the chain is compared state by state
				assertEquals(chain(emf.model), chain(ours.model), "depth " + depth);
				assertEquals(depth - 1, chain(ours.model).size(), "depth " + depth);
			} else {
				assertTrue(ours.message.contains("deeper than " + StatechartResources.MAX_ELEMENT_DEPTH), ours.message);
			}
		}
	}

	/**
	 * What the streaming writer cannot write as EMF does (a reference out of the model, a proxy,
	 * text XML cannot hold, another encoding) is written or refused by EMF, as before.
	 */
	@Test
	void whatTheStreamingWriterDoesNotKnowIsLeftToEmf() throws IOException {
		StatechartFactory factory = StatechartFactory.eINSTANCE;
		List<java.util.function.Consumer<Model>> changes = List.of(
				model -> model.getTransitions().get(0).setTarget(factory.createNode()),
				model -> {
					Node proxy = factory.createNode();
					((InternalEObject) proxy).eSetProxyURI(URI.createURI("other.stct#//@nodes.0"));
					model.getTransitions().get(0).setSource(proxy);
				},
				model -> {
					Variable loose = factory.createVariable();
					model.getNodes().get(0).getVariables().add(loose);
				},
				model -> model.getNodes().get(0).setName("control \u0001 character"),
				model -> model.getNodes().get(0).setLabel("lone \ud800 surrogate"),
				model -> model.getNodes().get(0).setLabel("not a character \uffff"),
				model -> model.getNodes().get(0).getChildren().get(0).setActivity("fine: \u00e9 \ud83e\udd16 & < > \" ' \t\r\n"));
		Map<Object, Object> options = Map.of(XMLResource.OPTION_ENCODING, "ASCII", XMLResource.OPTION_SAVE_TYPE_INFORMATION, Boolean.FALSE,
				XMLResource.OPTION_SKIP_ESCAPE_URI, Boolean.FALSE);
		int i = 0;
		for (var change : changes) {
			Model model = StatechartResources.load(REPOSITORY.resolve("tests/data/legacy-kse/Goalie/Goalie.stct"));
			change.accept(model);
			String ours = save(model, options);
			boolean streamed = StatechartResources.streamed(model.eResource());
			Map<Object, Object> emfOnly = new java.util.HashMap<>(options);
			emfOnly.put(StatechartResources.OPTION_STREAMING, Boolean.FALSE);
			assertEquals(save(model, emfOnly), ours, "change " + i);
			assertEquals(i == changes.size() - 1, streamed, "change " + i + ": " + StatechartResources.fallbackReason(model.eResource()));
			i++;
		}
		// other options are EMF's
		Model model = StatechartResources.load(REPOSITORY.resolve("tests/data/legacy-kse/Goalie/Goalie.stct"));
		Map<Object, Object> utf8 = Map.of(XMLResource.OPTION_ENCODING, "UTF-8");
		String written = save(model, utf8);
		assertFalse(StatechartResources.streamed(model.eResource()));
		assertTrue(written.startsWith("<?xml version=\"1.0\" encoding=\"UTF-8\"?>"), written);
	}

	/**
	 * The writer finds a transition's end from the states above it and its place near the last
	 * end's (ADR 0026), the whole of a list when it is not near, and an identity table once long
	 * lists have been searched enough: transitions that jump about lists of 100, 300 and 3,000
	 * states, and about a chain 60 deep, are written as EMF writes them; an end that is a state of
	 * another model is still declined after the table is made.
	 */
	@Test
	void transitionsThatJumpAboutLongListsAreWrittenAsEmfDoes() throws IOException {
		StatechartFactory factory = StatechartFactory.eINSTANCE;
		Random random = new Random(SEED);
		Model model = factory.createModel();
		model.setName("Jumps");
		List<Node> states = new ArrayList<>();
		for (int size : new int[] { 100, 300, 3_000 }) {
			Node parent = factory.createNode();
			parent.setName("list of " + size);
			model.getNodes().add(parent);
			for (int i = 0; i < size; i++) {
				Node state = factory.createNode();
				state.setName(size + "." + i);
				parent.getChildren().add(state);
				states.add(state);
			}
		}
		Node parent = model.getNodes().get(0);
		for (int level = 0; level < 60; level++) {
			Node child = factory.createNode();
			child.setLabel("level " + level);
			parent.getChildren().add(random.nextInt(parent.getChildren().size() + 1), child);
			states.add(child);
			parent = child;
		}
		// neighbours first (the windows), then jumps (whole lists, then the table)
		for (int i = 0; i + 1 < states.size(); i++) {
			Transition transition = factory.createTransition();
			transition.setSource(states.get(i));
			transition.setTarget(states.get(i + 1));
			model.getTransitions().add(transition);
		}
		for (int i = 0; i < 20_000; i++) {
			Transition transition = factory.createTransition();
			transition.setSource(states.get(random.nextInt(states.size())));
			transition.setTarget(states.get(random.nextInt(states.size())));
			model.getTransitions().add(transition);
		}
		byte[] emf = StatechartResources.toBytes(EcoreUtil.copy(model), false);
		Model copy = EcoreUtil.copy(model);
		byte[] ours = StatechartResources.toBytes(copy);
		StatechartResources.attach(copy, directory.resolve("jumps.stct"));
		assertArrayEquals(emf, StatechartResources.toBytes(copy), "the streaming writer writes other bytes than EMF");
		assertTrue(StatechartResources.streamed(copy.eResource()), () -> StatechartResources.fallbackReason(copy.eResource()));
		assertArrayEquals(emf, ours, "the streaming writer writes other bytes than EMF (scratch resource)");

		Path file = directory.resolve("jumps-read.stct");
		Files.write(file, emf);
		Model read = StatechartResources.load(file);
		assertTrue(StatechartResources.streamed(read.eResource()), () -> StatechartResources.fallbackReason(read.eResource()));
		assertSameModel(StatechartResources.load(file, false), read, "jumps");

		// a state of another model, after 20,000 jumps have made the writer use its table
		Transition stray = factory.createTransition();
		stray.setSource(states.get(0));
		stray.setTarget(factory.createNode());
		model.getTransitions().add(stray);
		StatechartResources.attach(model, directory.resolve("stray.stct"));
		Map<Object, Object> options = Map.of(XMLResource.OPTION_ENCODING, "ASCII", XMLResource.OPTION_SAVE_TYPE_INFORMATION, Boolean.FALSE,
				XMLResource.OPTION_SKIP_ESCAPE_URI, Boolean.FALSE);
		String written = save(model, options);
		assertFalse(StatechartResources.streamed(model.eResource()), "a transition to a state of no model is EMF's to write");
		Map<Object, Object> emfOnly = new java.util.HashMap<>(options);
		emfOnly.put(StatechartResources.OPTION_STREAMING, Boolean.FALSE);
		assertEquals(save(model, emfOnly), written);
	}

	/**
	 * The reader resolves a transition's end where it reads it when the state is already read, and
	 * at the end of the file otherwise: transitions before the states, between them, and to states
	 * of a later {@code <nodes>} give EMF's model.
	 */
	@Test
	void transitionsBeforeTheirStatesAreReadAsEmfDoes() throws IOException {
		String first = "  <nodes name=\"a\" type=\"OR\">\n    <Children name=\"a1\"/>\n    <Children name=\"a2\" type=\"OR\">\n      <Children name=\"a21\"/>\n    </Children>\n  </nodes>\n";
		String second = "  <nodes name=\"b\">\n    <Children name=\"b1\" label=\"b1\"/>\n  </nodes>\n";
		String early = "  <transitions name=\"early\" source=\"//@nodes.1/@Children.0\" target=\"//@nodes.0/@Children.1/@Children.0\"/>\n";
		String between = "  <transitions name=\"between\" source=\"//@nodes.0/@Children.1/@Children.0\" target=\"//@nodes.1/@Children.0\"/>\n";
		String late = "  <transitions name=\"late\" source=\"//@nodes.1\" target='//@nodes.0/@Children.0'/>\n";
		String end = "</statechart:Model>\n";
		List<String> files = List.of(HEADER + ROOT + ">\n" + early + first + second + late + end, HEADER + ROOT + ">\n" + first + between + second + late + end,
				HEADER + ROOT + ">\n" + first + early.replace("//@nodes.1/@Children.0", "//@nodes.0/@Children.2") + second + end);
		int i = 0;
		for (String text : files) {
			Path file = directory.resolve("order" + i++ + ".stct");
			Files.writeString(file, text, StandardCharsets.US_ASCII);
			Outcome ours = Outcome.of(file, true);
			Outcome emf = Outcome.of(file, false);
			assertEquals(emf.message, ours.message, text);
			if (i < 3) {
				assertTrue(StatechartResources.streamed(ours.model.eResource()), () -> StatechartResources.fallbackReason(ours.model.eResource()));
				assertSameModel(emf.model, ours.model, text);
			} else {
				assertTrue(ours.message != null && ours.model == null, "a path to no state is refused: " + text);
			}
		}
	}

	/**
	 * The reader gives each state its children in one step (ADR 0026): the lists and containers
	 * it leaves behave as those of EMF's reader when the model is then edited.
	 */
	@Test
	void aModelReadIsEditedAsEmfsIs() throws IOException {
		Path file = REPOSITORY.resolve("tests/data/legacy-kse/Goalie/Goalie.stct");
		List<Model> models = new ArrayList<>();
		List<List<String>> observed = new ArrayList<>();
		for (boolean streaming : new boolean[] { true, false }) {
			Model model = StatechartResources.load(file, streaming);
			assertEquals(streaming, StatechartResources.streamed(model.eResource()));
			Node top = model.getNodes().get(0);
			Node composite = null;
			for (Iterator<EObject> it = model.eAllContents(); it.hasNext() && composite == null;) {
				if (it.next() instanceof Node state && state != top && state.getChildren().size() > 1) {
					composite = state;
				}
			}
			assertNotNull(composite, "the Goalie has a composite state inside its top state");
			List<String> heard = new ArrayList<>();
			composite.eAdapters().add(new org.eclipse.emf.ecore.util.EContentAdapter() {
				@Override
				public void notifyChanged(org.eclipse.emf.common.notify.Notification notification) {
					super.notifyChanged(notification);
					heard.add(notification.getEventType() + " " + notification.getPosition());
				}
			});
			Node added = StatechartFactory.eINSTANCE.createNode();
			added.setName("added");
			composite.getChildren().add(0, added);
			Node moved = composite.getChildren().get(composite.getChildren().size() - 1);
			top.getChildren().add(moved);
			composite.getChildren().move(0, 1);
			composite.getChildren().get(0).setName("renamed");
			assertEquals(composite, added.getFather_of(), "the container of a state added to a state read");
			assertEquals(top, moved.getFather_of(), "the container of a state moved out of a state read");
			for (Iterator<EObject> it = model.eAllContents(); it.hasNext();) {
				EObject element = it.next();
				heard.add(element.eContainingFeature().getName() + " " + ((InternalEObject) element).eContainerFeatureID());
			}
			heard.add(new String(StatechartResources.toBytes(model), StandardCharsets.US_ASCII));
			models.add(model);
			observed.add(heard);
		}
		assertSameModel(models.get(1), models.get(0), "edited");
		assertEquals(observed.get(1), observed.get(0), "notifications, containing features and bytes after the same edits");
	}

	/** The names of the states of a chain, and where the chain branches or ends. */
	private static List<String> chain(Model model) {
		List<String> chain = new ArrayList<>();
		for (Iterator<EObject> it = model.eAllContents(); it.hasNext();) {
			Node state = (Node) it.next();
			chain.add(state.getName() + " " + state.getChildren().size() + " " + (state.eContainer() instanceof Node parent ? parent.getChildren().indexOf(state) : -1));
		}
		return chain;
	}

	/** The bytes a save writes, or "refused: " and EMF's message. */
	private static String save(Model model, Map<Object, Object> options) {
		ByteArrayOutputStream bytes = new ByteArrayOutputStream();
		try {
			model.eResource().save(bytes, options);
			return bytes.toString(StandardCharsets.ISO_8859_1);
		} catch (IOException | RuntimeException e) {
			return "refused: " + e;
		}
	}

	/** A load's model, or its message. */
	private record Outcome(Model model, String message) {
		static Outcome of(Path file, boolean streaming) {
			try {
				return new Outcome(StatechartResources.load(file, streaming), null);
			} catch (IOException e) {
				return new Outcome(null, e.getMessage());
			}
		}

		/** Loaded with KSE's options but the parser's limits {@code limits}; the message is the parser's as EMF passes it on. */
		static Outcome of(Path file, boolean streaming, Map<String, String> limits) {
			Map<Object, Object> options = new java.util.HashMap<>();
			options.put(XMLResource.OPTION_DEFER_IDREF_RESOLUTION, Boolean.TRUE);
			options.put(XMLResource.OPTION_PARSER_FEATURES, Map.of("http://apache.org/xml/features/disallow-doctype-decl", Boolean.TRUE));
			options.put(XMLResource.OPTION_PARSER_PROPERTIES, limits);
			if (!streaming) {
				options.put(StatechartResources.OPTION_STREAMING, Boolean.FALSE);
			}
			Resource resource = StatechartResources.newResourceSet().createResource(URI.createFileURI(file.toAbsolutePath().toString()));
			try {
				resource.load(options);
				return new Outcome((Model) resource.getContents().get(0), null);
			} catch (IOException e) {
				return new Outcome(null, e.getMessage());
			}
		}
	}

	/** The same elements and values, every element at the same URI fragment, every reference to the same place. */
	private static void assertSameModel(Model expected, Model actual, String what) {
		assertTrue(EcoreUtil.equals(expected, actual), what + ": another model than EMF reads");
		assertEquals(fragments(expected), fragments(actual), what + ": elements at other URI fragments");
		assertEquals(references(expected), references(actual), what + ": references that lead elsewhere");
		assertEquals(expected.eResource().getErrors().size(), actual.eResource().getErrors().size(), what + ": errors");
	}

	private static List<String> fragments(Model model) {
		List<String> fragments = new ArrayList<>();
		Resource resource = model.eResource();
		for (Iterator<EObject> it = resource.getAllContents(); it.hasNext();) {
			EObject element = it.next();
			fragments.add(resource.getURIFragment(element));
			if (resource.getEObject(fragments.get(fragments.size() - 1)) != element) {
				fail("the fragment " + fragments.get(fragments.size() - 1) + " does not lead back to its element");
			}
		}
		return fragments;
	}

	private static List<String> references(Model model) {
		List<String> references = new ArrayList<>();
		for (Iterator<EObject> it = model.eAllContents(); it.hasNext();) {
			EObject element = it.next();
			for (EReference reference : element.eClass().getEAllReferences()) {
				if (reference.isContainment() || reference.isContainer()) {
					continue;
				}
				Object value = element.eGet(reference, false);
				for (Object target : value instanceof List<?> list ? list : java.util.Collections.singletonList(value)) {
					references.add(reference.getName() + " " + (target == null ? "none" : EcoreUtil.getURI((EObject) target).toString()));
				}
			}
		}
		return references;
	}
}
