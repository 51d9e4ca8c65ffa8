package org.kse.model;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFileAttributeView;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.Map;
import java.util.UUID;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EAttribute;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.InternalEObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.resource.impl.FileURIHandlerImpl;
import org.eclipse.emf.ecore.resource.impl.PlatformResourceURIHandlerImpl;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.emf.ecore.xmi.XMLResource;
import org.eclipse.emf.common.util.WrappedException;
import org.eclipse.emf.ecore.xmi.XMLLoad;
import org.eclipse.emf.ecore.xmi.impl.SAXXMIHandler;
import org.eclipse.emf.ecore.xmi.impl.XMILoadImpl;
import org.eclipse.emf.ecore.xmi.impl.XMIResourceFactoryImpl;
import org.eclipse.emf.ecore.xmi.impl.XMIResourceImpl;
import org.xml.sax.Attributes;
import org.xml.sax.SAXException;
import org.xml.sax.SAXParseException;
import org.xml.sax.helpers.DefaultHandler;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.StatechartPackage;

/**
 * Loading and saving {@code .stct} files, inside or outside OSGi. Saves are atomic:
 * the new content is written beside the file and moved over it, so a crash never
 * leaves half a model behind.
 */
public final class StatechartResources {

	public static final String FILE_EXTENSION = "stct";

	/** The deepest nesting of XML elements a model file may have: states nest twice per level. */
	public static final int MAX_ELEMENT_DEPTH = 10_000;

	private StatechartResources() {
	}

	/**
	 * A resource set that knows the statechart package and the .stct extension, and that never
	 * loads anything it was not asked to: a model is one file, and a model from someone else must
	 * not make KSE open other files or reach the network. A reference into another document (an
	 * href, a proxy) and an unknown nsURI stay unresolved, which validation reports; only file
	 * and platform URIs can be read at all.
	 */
	public static ResourceSet newResourceSet() {
		ResourceSet resourceSet = new ResourceSetImpl() {
			@Override
			public Resource getResource(URI uri, boolean loadOnDemand) {
				return super.getResource(uri, false);
			}
		};
		resourceSet.getURIConverter().getURIHandlers()
				.removeIf(handler -> !(handler instanceof FileURIHandlerImpl || handler instanceof PlatformResourceURIHandlerImpl));
		resourceSet.getPackageRegistry().put(StatechartPackage.eNS_URI, StatechartPackage.eINSTANCE);
		Resource.Factory factory = new XMIResourceFactoryImpl() {
			@Override
			public Resource createResource(URI uri) {
				return new PositionedResource(uri);
			}
		};
		resourceSet.getResourceFactoryRegistry().getExtensionToFactoryMap().put(FILE_EXTENSION, factory);
		resourceSet.getResourceFactoryRegistry().getExtensionToFactoryMap().put("*", factory);
		return resourceSet;
	}

	/**
	 * Loads the model of a file.
	 *
	 * @throws IOException with a message naming the file when it is missing or is not a statechart model
	 */
	public static Model load(Path file) throws IOException {
		return load(newResourceSet(), file);
	}

	public static Model load(ResourceSet resourceSet, Path file) throws IOException {
		return load(resourceSet, file, loadOptions());
	}

	private static Model load(ResourceSet resourceSet, Path file, Map<Object, Object> options) throws IOException {
		checkReadable(file);
		Resource resource = resourceSet.createResource(URI.createFileURI(file.toAbsolutePath().toString()));
		try {
			resource.load(options);
		} catch (IOException | RuntimeException e) {
			throw new IOException(loadFailure(file, e), e);
		}
		if (resource.getContents().isEmpty() || !(resource.getContents().get(0) instanceof Model model)) {
			throw new IOException(file + ": not a statechart model (its root element is not statechart:Model)");
		}
		return model;
	}

	/**
	 * Refuses, with a message naming it, a path that is not a file one can read to its end: a
	 * missing file, a folder, a device such as /dev/zero or a pipe.
	 */
	public static void checkReadable(Path file) throws IOException {
		if (Files.isDirectory(file)) {
			throw new IOException(file + ": is a folder, not a file");
		}
		if (!Files.exists(file)) {
			throw new IOException(file + ": no such file");
		}
		if (!Files.isRegularFile(file)) {
			throw new IOException(file + ": not a regular file");
		}
	}

	/**
	 * Refuses a model whose text an XML 1.0 file cannot hold (a control character pasted into a
	 * name, a lone surrogate): EMF would write a character reference that no parser reads back,
	 * so the saved file could never be opened again. The message names the element and the field.
	 */
	public static void checkWritable(Model model) throws IOException {
		if (allWritable(model)) {
			return;
		}
		for (var it = org.eclipse.emf.ecore.util.EcoreUtil.<EObject>getAllProperContents(java.util.List.of(model), false); it.hasNext();) {
			EObject element = it.next();
			for (EAttribute attribute : element.eClass().getEAllAttributes()) {
				if (element.eGet(attribute) instanceof String text) {
					int bad = unwritable(text);
					if (bad >= 0) {
						throw new IOException("cannot save: the " + attribute.getName() + " of " + describe(element) + " holds the character U+"
								+ String.format("%04X", (int) text.charAt(bad)) + " at position " + (bad + 1) + ", which a model file cannot hold");
					}
				}
			}
		}
	}

	/**
	 * Whether every text of the model is one a file can hold, found without EMF's reflection (a
	 * save of a large model would spend more time here than writing it); when not, the generic
	 * walk above finds the first such text in the order it reports it.
	 */
	private static boolean allWritable(Model model) {
		if (unwritable(model.getName()) >= 0) {
			return false;
		}
		java.util.ArrayDeque<org.kse.model.statechart.Node> states = new java.util.ArrayDeque<>(model.getNodes());
		while (!states.isEmpty()) {
			org.kse.model.statechart.Node state = states.pop();
			if (state.eClass() != StatechartPackage.Literals.NODE || unwritable(state.getName()) >= 0 || unwritable(state.getLabel()) >= 0
					|| unwritable(state.getType()) >= 0 || unwritable(state.getActivity()) >= 0) {
				return false;
			}
			states.addAll(state.getChildren());
		}
		for (org.kse.model.statechart.Transition transition : model.getTransitions()) {
			if (transition.eClass() != StatechartPackage.Literals.TRANSITION || unwritable(transition.getTE()) >= 0 || unwritable(transition.getName()) >= 0) {
				return false;
			}
		}
		for (org.kse.model.statechart.Variable variable : model.getVariables()) {
			if (variable.eClass() != StatechartPackage.Literals.VARIABLE || unwritable(variable.getName()) >= 0 || unwritable(variable.getType()) >= 0) {
				return false;
			}
		}
		return model.eClass() == StatechartPackage.Literals.MODEL;
	}

	/** The index of the first character XML 1.0 cannot hold, or -1. */
	private static int unwritable(String text) {
		if (text == null) {
			return -1;
		}
		for (int i = 0, length = text.length(); i < length; i++) {
			char c = text.charAt(i);
			if (c >= 0x20 && c < 0xD800) {
				// nearly every character: decided with two comparisons
				continue;
			}
			boolean allowed = c == '\t' || c == '\n' || c == '\r' || (c >= 0x20 && c <= 0xD7FF) || (c >= 0xE000 && c <= 0xFFFD);
			if (Character.isHighSurrogate(c) && i + 1 < text.length() && Character.isLowSurrogate(text.charAt(i + 1))) {
				i++;
				continue;
			}
			if (!allowed) {
				return i;
			}
		}
		return -1;
	}

	private static String describe(EObject element) {
		if (element instanceof org.kse.model.statechart.Node node) {
			return "state " + (node.getLabel() == null ? "" : node.getLabel() + " ") + "(" + node.getName() + ")";
		}
		if (element instanceof org.kse.model.statechart.Transition transition) {
			return "transition " + transition.getName();
		}
		if (element instanceof org.kse.model.statechart.Variable variable) {
			return "variable " + variable.getName();
		}
		return element instanceof Model model ? "model " + model.getName() : element.eClass().getName();
	}

	/** Puts a model into a new resource for {@code file}; call {@link #save} to write it. */
	public static Resource attach(Model model, Path file) {
		Resource resource = newResourceSet().createResource(URI.createFileURI(file.toAbsolutePath().toString()));
		resource.getContents().add(model);
		return resource;
	}

	/** Writes the model's resource to its file, atomically. */
	public static void save(Model model) throws IOException {
		Resource resource = model.eResource();
		if (resource == null) {
			throw new IOException("the model is not attached to a file");
		}
		Path target = Path.of(resource.getURI().toFileString());
		// straight into the file beside the target: a large model is not held twice in memory
		writeAtomically(target, output -> saveWritable(model, resource, output, saveOptions()));
	}

	/**
	 * Saves a model whose text a file can hold, and refuses one with {@link #checkWritable}'s
	 * message. The streaming writer checks every text as it writes it and leaves a model with such
	 * text to EMF; so the separate walk over the model is only made when EMF wrote it or failed
	 * (a walk that would cost a large model as much as writing it).
	 */
	private static void saveWritable(Model model, Resource resource, java.io.OutputStream output, Map<Object, Object> options) throws IOException {
		try {
			resource.save(output, options);
		} catch (IOException | RuntimeException e) {
			checkWritable(model);
			throw e;
		}
		if (!streamed(resource)) {
			checkWritable(model);
		}
	}

	/** Saves a model to a file (detached from any previous resource). */
	public static void save(Model model, Path file) throws IOException {
		if (model.eResource() == null || !file.toAbsolutePath().toString().equals(model.eResource().getURI().toFileString())) {
			attach(model, file);
		}
		save(model);
	}

	/** Serializes a model as the bytes its file would hold, leaving the model where it was. */
	public static byte[] toBytes(Model model) throws IOException {
		return toBytes(model, saveOptions());
	}

	private static byte[] toBytes(Model model, Map<Object, Object> options) throws IOException {
		ByteArrayOutputStream bytes = new ByteArrayOutputStream();
		if (model.eResource() != null) {
			saveWritable(model, model.eResource(), bytes, options);
			return bytes.toByteArray();
		}
		Resource scratch = newResourceSet().createResource(URI.createFileURI("model.stct"));
		scratch.getContents().add(model);
		try {
			saveWritable(model, scratch, bytes, options);
		} finally {
			scratch.getContents().remove(model);
		}
		return bytes.toByteArray();
	}

	/**
	 * Replaces {@code target} with {@code content} in one step. A new file gets the
	 * permissions any new file gets (the umask applies); an existing file keeps its own.
	 */
	public static void writeAtomically(Path target, byte[] content) throws IOException {
		writeAtomically(target, output -> output.write(content));
	}

	/** What writes a file's content; a failure leaves the file as it was. */
	@FunctionalInterface
	private interface Content {
		void writeTo(java.io.OutputStream output) throws IOException;
	}

	private static void writeAtomically(Path target, Content content) throws IOException {
		if (Files.isDirectory(target)) {
			throw new IOException(target + ": is a folder; give the name of a file to write");
		}
		Path directory = target.toAbsolutePath().getParent();
		if (Files.exists(directory) && !Files.isDirectory(directory)) {
			throw new IOException(directory + ": not a folder, so " + target.getFileName() + " cannot be written in it");
		}
		Files.createDirectories(directory);
		Path temporary = directory.resolve("." + target.getFileName() + "." + UUID.randomUUID() + ".tmp");
		try {
			try (java.io.OutputStream output = new java.io.BufferedOutputStream(Files.newOutputStream(temporary, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE), 1 << 16)) {
				content.writeTo(output);
			}
			if (Files.exists(target) && Files.getFileStore(directory).supportsFileAttributeView(PosixFileAttributeView.class)) {
				Files.setPosixFilePermissions(temporary, Files.getPosixFilePermissions(target));
			}
			try {
				Files.move(temporary, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
			} catch (AtomicMoveNotSupportedException e) {
				Files.move(temporary, target, StandardCopyOption.REPLACE_EXISTING);
			}
		} finally {
			Files.deleteIfExists(temporary);
		}
	}

	/**
	 * Load and save option: {@code Boolean.FALSE} leaves the file to EMF's XMI parser and
	 * serializer alone, without the streaming reader and writer (ADR 0026). For comparing the two.
	 */
	public static final String OPTION_STREAMING = "org.kse.model.streaming";

	private static final String DEPTH_PROPERTY = "jdk.xml.maxElementDepth";
	private static final String GENERAL_ENTITY_PROPERTY = "jdk.xml.maxGeneralEntitySizeLimit";
	private static final String TOTAL_ENTITY_PROPERTY = "jdk.xml.totalEntitySizeLimit";
	/** The parser properties a load of KSE's may set; the streaming reader follows each of them. */
	private static final java.util.Set<String> LIMIT_PROPERTIES = java.util.Set.of(DEPTH_PROPERTY, GENERAL_ENTITY_PROPERTY, TOTAL_ENTITY_PROPERTY);
	/**
	 * The SAX feature that makes the parser refuse a DOCTYPE where it begins, before it reads or
	 * fetches anything of it: every reader of XML from a stranger in KSE sets it.
	 */
	public static final String DISALLOW_DOCTYPE = "http://apache.org/xml/features/disallow-doctype-decl";
	private static final String DOCTYPE_REFUSED = "a model file may not declare a DOCTYPE (KSE files have none)";

	/**
	 * Loads a model with or without the streaming reader: {@code load(file, false)} is what
	 * {@link #load(Path)} gives for every file the streaming reader does not take.
	 */
	public static Model load(Path file, boolean streaming) throws IOException {
		Map<Object, Object> options = loadOptions();
		if (!streaming) {
			options.put(OPTION_STREAMING, Boolean.FALSE);
		}
		return load(newResourceSet(), file, options);
	}

	/** The bytes of a model as {@link #toBytes(Model)} gives them, with or without the streaming writer. */
	public static byte[] toBytes(Model model, boolean streaming) throws IOException {
		Map<Object, Object> options = saveOptions();
		if (!streaming) {
			options.put(OPTION_STREAMING, Boolean.FALSE);
		}
		return toBytes(model, options);
	}

	/**
	 * Whether the last load or save of a resource of {@link #newResourceSet()} went through the
	 * streaming reader or writer; for tests and benchmarks that must know which one ran.
	 */
	public static boolean streamed(Resource resource) {
		return resource instanceof PositionedResource positioned && positioned.fallback == null;
	}

	/** Why the last load or save of a resource was left to EMF, or null when it was streamed: for tests' messages. */
	public static String fallbackReason(Resource resource) {
		return resource instanceof PositionedResource positioned ? positioned.fallback : "not a resource of StatechartResources";
	}

	private static Map<Object, Object> loadOptions() {
		Map<Object, Object> options = new HashMap<>();
		options.put(XMLResource.OPTION_DEFER_IDREF_RESOLUTION, Boolean.TRUE);
		// No model file has a DOCTYPE, and a DOCTYPE is how hostile XML attacks a parser: entities
		// that expand a billion times, external DTDs and entities fetched from anywhere. Refused
		// where it begins, on EMF's way as on the streaming reader's (which leaves it to EMF).
		options.put(XMLResource.OPTION_PARSER_FEATURES, Map.of(DISALLOW_DOCTYPE, Boolean.TRUE));
		// Every model KSE saves must load again. The JDK's parser refuses elements nested deeper
		// than 100, but KSE writes deeper models (a formula nests its terms); and it refuses more
		// than 100,000 characters of entities (JDK 25), which some 50,000 guards holding && reach.
		// Without a DOCTYPE the entity limits count only the five predefined entities (&amp; one,
		// &quot; two...), which cost the parser nothing: lifted ("0" is none). All set on this
		// parser only, not for the whole JVM.
		options.put(XMLResource.OPTION_PARSER_PROPERTIES, Map.of(DEPTH_PROPERTY, String.valueOf(MAX_ELEMENT_DEPTH), GENERAL_ENTITY_PROPERTY, "0",
				TOTAL_ENTITY_PROPERTY, "0"));
		return options;
	}

	private static Map<Object, Object> saveOptions() {
		Map<Object, Object> options = new HashMap<>();
		// the original tool's files are ASCII with character references; keep that
		options.put(XMLResource.OPTION_ENCODING, "ASCII");
		options.put(XMLResource.OPTION_SAVE_TYPE_INFORMATION, Boolean.FALSE);
		// A reference that points nowhere is written as an href; its text must be escaped like any
		// other value, or the file cannot be read back (EMF skips escaping URIs by default).
		options.put(XMLResource.OPTION_SKIP_ESCAPE_URI, Boolean.FALSE);
		return options;
	}

	/**
	 * An XMI resource whose loading errors say where they are: an element that EMF cannot place
	 * (a state where a transition belongs, one value where a list is expected) raises a Java
	 * exception without a position; here it becomes a parse error at the element's line and column.
	 */
	private static final class PositionedResource extends XMIResourceImpl {
		/** While loading: the element of each positional path's container, found once. */
		private Map<String, EObject> containers;
		/** While saving: each element's positional fragment, and each element's index in its container's list. */
		private Map<EObject, String> fragments;
		private Map<EObject, Integer> positions;
		/** Why the last load or save was left to EMF, or null when the streaming reader or writer did it. */
		private String fallback = "not loaded or saved yet";

		PositionedResource(URI uri) {
			super(uri);
		}

		/**
		 * The file is read by {@link StctReader} when it is in the one dialect KSE writes, and by
		 * EMF's parser otherwise (ADR 0026): the same bytes, so EMF's messages and rules apply to
		 * every file the streaming reader does not take.
		 */
		@Override
		public void doLoad(java.io.InputStream inputStream, Map<?, ?> options) throws IOException {
			fallback = "load options or an input stream that only EMF's parser takes";
			java.io.InputStream input = inputStream;
			byte[] bytes = null;
			try {
				if (streamingReadable(inputStream, options)) {
					int[] length = new int[1];
					bytes = SpareBuffers.readAll(inputStream, length);
					try {
						StctReader.Result result = StctReader.read(bytes, length[0], depthLimit(options), entityLimit(options));
						setEncoding(result.encoding());
						setXMLVersion("1.0");
						getContents().add(result.model());
						fallback = null;
						return;
					} catch (StctReader.NotOurs e) {
						fallback = e.getMessage();
						input = new java.io.ByteArrayInputStream(bytes, 0, length[0]);
					}
				}
				containers = new HashMap<>();
				try {
					super.doLoad(input, options);
				} finally {
					containers = null;
				}
			} finally {
				if (bytes != null) {
					SpareBuffers.giveInput(bytes);
				}
			}
		}

		/**
		 * Saved by {@link StctWriter} when the options are KSE's and the model is one it can write,
		 * by EMF's serializer otherwise: the bytes are the same either way (ADR 0026).
		 */
		@Override
		public void doSave(java.io.OutputStream outputStream, Map<?, ?> options) throws IOException {
			fallback = "save options, contents or an output stream that only EMF's serializer takes";
			if (streamingWritable(outputStream, options)) {
				try {
					// EMF's default when the options name no line delimiter: the JVM's, as it started
					StctWriter.write((Model) getContents().get(0), System.lineSeparator(), outputStream);
					outputStream.flush();
					fallback = null;
					return;
				} catch (StctReader.NotOurs e) {
					fallback = e.getMessage();
				}
			}
			fragments = new IdentityHashMap<>();
			positions = new IdentityHashMap<>();
			try {
				super.doSave(outputStream, options);
			} finally {
				fragments = null;
				positions = null;
			}
		}

		/**
		 * An XMI resource walks every tree attached to it or detached from it to keep its ID maps,
		 * even without any: a model saved under another name is walked twice, a model read once.
		 * Without an ID map, modification tracking or intrinsic IDs, the walk does nothing, and is
		 * left out; with any of them it is EMF's as before.
		 */
		@Override
		protected boolean isAttachedDetachedHelperRequired() {
			return eObjectToIDMap != null || idToEObjectMap != null || useUUIDs() || isTrackingModification() || getIntrinsicIDToEObjectMap() != null;
		}

		/** Options that change nothing for a file of KSE's dialect; any other is EMF's to apply. */
		private static final java.util.Set<Object> PLAIN_LOAD_OPTIONS = java.util.Set.of(XMLResource.OPTION_DEFER_IDREF_RESOLUTION,
				XMLResource.OPTION_PARSER_PROPERTIES, XMLResource.OPTION_PARSER_FEATURES, OPTION_STREAMING);

		private boolean streamingReadable(java.io.InputStream inputStream, Map<?, ?> options) {
			if (options != null && (Boolean.FALSE.equals(options.get(OPTION_STREAMING)) || !PLAIN_LOAD_OPTIONS.containsAll(options.keySet()))) {
				return false;
			}
			// the limits are followed by the reader; any other property or feature may change what the parser reads
			if (options != null && options.get(XMLResource.OPTION_PARSER_PROPERTIES) instanceof Map<?, ?> properties
					&& !LIMIT_PROPERTIES.containsAll(properties.keySet())) {
				return false;
			}
			// the reader leaves every DOCTYPE to the parser, so refusing them changes nothing for a file it reads
			if (options != null && options.get(XMLResource.OPTION_PARSER_FEATURES) instanceof Map<?, ?> features
					&& !java.util.Set.of(DISALLOW_DOCTYPE).containsAll(features.keySet())) {
				return false;
			}
			return !(inputStream instanceof org.eclipse.emf.ecore.resource.URIConverter.Loadable)
					&& !(inputStream instanceof org.eclipse.emf.ecore.resource.URIConverter.Readable) && getContents().isEmpty();
		}

		/**
		 * The parser's element depth limit for this load: the one the options set, or, without it,
		 * the JDK's as configured (100 in JDK 25); the reader leaves a file that reaches it to the parser.
		 */
		private static int depthLimit(Map<?, ?> options) {
			return parserLimit(options, DEPTH_PROPERTY, StctReader.ParserLimits.ELEMENT_DEPTH);
		}

		/**
		 * The parser's entity size limit for this load, the smaller of the general and the total one,
		 * each as the options set it or, without it, as the JDK is configured (100,000 in JDK 25;
		 * none in KSE's load options). The reader leaves a file that reaches it to the parser, so the
		 * two read or refuse the same files whatever the options.
		 */
		private static int entityLimit(Map<?, ?> options) {
			return Math.min(parserLimit(options, GENERAL_ENTITY_PROPERTY, StctReader.ParserLimits.GENERAL_ENTITY_SIZE),
					parserLimit(options, TOTAL_ENTITY_PROPERTY, StctReader.ParserLimits.TOTAL_ENTITY_SIZE));
		}

		/** A limit of the parser as the load options set it (0 or less: none), {@code otherwise} when they do not; 0 when the value is no number. */
		private static int parserLimit(Map<?, ?> options, String property, int otherwise) {
			Object properties = options == null ? null : options.get(XMLResource.OPTION_PARSER_PROPERTIES);
			if (properties instanceof Map<?, ?> map && map.get(property) != null) {
				try {
					int limit = Integer.parseInt(String.valueOf(map.get(property)).trim());
					return limit <= 0 ? Integer.MAX_VALUE : limit;
				} catch (NumberFormatException e) {
					// the reader leaves the file to the parser, which says what it makes of the value
					return 0;
				}
			}
			return otherwise;
		}

		private boolean streamingWritable(java.io.OutputStream outputStream, Map<?, ?> options) {
			if (options == null || Boolean.FALSE.equals(options.get(OPTION_STREAMING))) {
				return false;
			}
			Map<Object, Object> rest = new HashMap<>(options);
			rest.remove(OPTION_STREAMING);
			return rest.equals(saveOptions()) && "1.0".equals(getXMLVersion()) && getContents().size() == 1 && getContents().get(0) instanceof Model
					&& (eObjectToIDMap == null || eObjectToIDMap.isEmpty()) && (eObjectToExtensionMap == null || eObjectToExtensionMap.isEmpty())
					&& !(outputStream instanceof org.eclipse.emf.ecore.resource.URIConverter.Saveable);
		}

		/**
		 * The original tool's files refer to states by position ({@code //@nodes.0/@Children.3}), and
		 * so do ours. EMF resolves each such reference from the root, splitting and interning the path
		 * each time; while loading, a reference's container is looked up once for all its siblings.
		 * Anything but a positional path (an ID) is EMF's.
		 */
		@Override
		public EObject getEObject(String uriFragment) {
			Map<String, EObject> known = containers;
			int slash = uriFragment == null ? -1 : uriFragment.lastIndexOf('/');
			if (known == null || slash <= 0 || uriFragment.charAt(0) != '/') {
				return super.getEObject(uriFragment);
			}
			String path = uriFragment.substring(0, slash);
			EObject container = known.get(path);
			if (container == null) {
				container = super.getEObject(path);
				if (container == null) {
					return null;
				}
				known.put(path, container);
			}
			return ((InternalEObject) container).eObjectForURIFragmentSegment(uriFragment.substring(slash + 1));
		}

		/**
		 * Saving writes each reference as its target's positional path, which EMF computes from the
		 * root with a linear search of every list on the way: a third of the time of saving a large
		 * model. Here each element's path is its container's (computed once) and its index (one pass
		 * over each list): the same text, as the original tool reads it. Elements with an ID, in
		 * another resource or reached through anything but a plain containment list are EMF's.
		 */
		@Override
		public String getURIFragment(EObject eObject) {
			if (fragments == null || (eObjectToIDMap != null && !eObjectToIDMap.isEmpty()) || eObject.eIsProxy()) {
				return super.getURIFragment(eObject);
			}
			String fragment = fragments.get(eObject);
			if (fragment == null) {
				fragment = positionalFragment((InternalEObject) eObject);
				if (fragment == null) {
					return super.getURIFragment(eObject);
				}
			}
			return fragment;
		}

		/** The positional fragment, remembered for the element and every container on its way; null where EMF must decide. */
		private String positionalFragment(InternalEObject element) {
			java.util.ArrayDeque<InternalEObject> chain = new java.util.ArrayDeque<>();
			String fragment = null;
			for (InternalEObject current = element; fragment == null; current = current.eInternalContainer()) {
				if (current == null || current.eIsProxy() || org.eclipse.emf.ecore.util.EcoreUtil.getID(current) != null) {
					return null;
				}
				fragment = fragments.get(current);
				if (fragment == null) {
					if (current.eDirectResource() == this) {
						fragment = "/" + getURIFragmentRootSegment(current);
						fragments.put(current, fragment);
					} else if (current.eDirectResource() != null) {
						return null;
					} else {
						chain.push(current);
					}
				}
			}
			while (!chain.isEmpty()) {
				InternalEObject child = chain.pop();
				String segment = segment(child);
				if (segment == null) {
					return null;
				}
				fragment = fragment + "/" + segment;
				fragments.put(child, fragment);
			}
			return fragment;
		}

		/** {@code @feature.index} as EMF writes it for an element of a containment list without keys; null for any other way of being contained. */
		private String segment(InternalEObject child) {
			EStructuralFeature feature = child.eContainingFeature();
			if (!(feature instanceof org.eclipse.emf.ecore.EReference reference) || !reference.isContainment() || !reference.getEKeys().isEmpty()) {
				return null;
			}
			if (!reference.isMany()) {
				return "@" + reference.getName();
			}
			Integer index = positions.get(child);
			if (index == null) {
				java.util.List<?> siblings = (java.util.List<?>) child.eInternalContainer().eGet(reference, false);
				for (int i = 0; i < siblings.size(); i++) {
					if (siblings.get(i) instanceof EObject sibling) {
						positions.put(sibling, i);
					}
				}
				index = positions.get(child);
			}
			return index == null ? null : "@" + reference.getName() + "." + index;
		}

		@Override
		protected XMLLoad createXMLLoad() {
			return new XMILoadImpl(createXMLHelper()) {
				@Override
				protected DefaultHandler makeDefaultHandler() {
					return new SAXXMIHandler(resource, helper, options) {
						@Override
						public void startElement(String uri, String localName, String name, Attributes attributes) throws SAXException {
							try {
								super.startElement(uri, localName, name, attributes);
							} catch (RuntimeException e) {
								throw positioned("the element <" + name + ">", e);
							}
						}

						@Override
						public void endElement(String uri, String localName, String name) {
							try {
								super.endElement(uri, localName, name);
							} catch (RuntimeException e) {
								throw new WrappedException(positioned("the end of <" + name + ">", e));
							}
						}

						@Override
						public void characters(char[] text, int start, int length) {
							try {
								super.characters(text, start, length);
							} catch (RuntimeException e) {
								throw new WrappedException(positioned("the text", e));
							}
						}

						/**
						 * References are resolved at the end of the document, where EMF records a broken one
						 * without a position; it is found again to name its line and column.
						 */
						@Override
						protected void handleForwardReferences(boolean isEndDocument) {
							int before = xmlResource.getErrors().size();
							try {
								super.handleForwardReferences(isEndDocument);
							} catch (RuntimeException e) {
								findBrokenReference();
								throw e;
							}
							if (xmlResource.getErrors().size() > before) {
								findBrokenReference();
							}
						}

						private void findBrokenReference() {
							for (SingleReference reference : forwardSingleReferences) {
								check(reference.getFeature(), reference.getValue(), reference.getLineNumber(), reference.getColumnNumber());
							}
							for (ManyReference reference : forwardManyReferences) {
								if (!reference.getFeature().isMany() && reference.getValues().length > 1) {
									throw new WrappedException(new SAXParseException("the reference in " + reference.getFeature().getName() + " names "
											+ reference.getValues().length + " elements; it takes one", null, null, reference.getLineNumber(), reference.getColumnNumber()));
								}
								for (Object value : reference.getValues()) {
									check(reference.getFeature(), value, reference.getLineNumber(), reference.getColumnNumber());
								}
							}
						}

						private void check(org.eclipse.emf.ecore.EStructuralFeature feature, Object id, int line, int column) {
							Object target;
							try {
								target = id instanceof String text ? xmlResource.getEObject(text) : id;
							} catch (RuntimeException e) {
								target = e;
							}
							if (target != null && !feature.getEType().isInstance(target)) {
								SAXParseException parse = new SAXParseException("the reference " + quote(String.valueOf(id)) + " in " + feature.getName() + " does not lead to a "
										+ feature.getEType().getName(), null, null, line, column);
								throw new WrappedException(parse);
							}
						}

						private SAXParseException positioned(String what, RuntimeException e) {
							String why = e instanceof ClassCastException ? "does not belong where it is"
									: "cannot be read (" + userText(rootCause(e)) + ")";
							SAXParseException parse = new SAXParseException(what + " " + why, locator);
							parse.initCause(e);
							return parse;
						}
					};
				}
			};
		}
	}

	/**
	 * Why a file is not a model, in the user's terms and with the line and column where the input
	 * has them: the XML parser's and EMF's diagnostics carry a position; a malformed number or
	 * reference (Java's NumberFormatException, raised while references are resolved at the end of
	 * the document) is found again in the text.
	 */
	private static String loadFailure(Path file, Throwable e) {
		for (Throwable cause = e; cause != null; cause = cause.getCause() == cause ? null : cause.getCause()) {
			if (cause instanceof SAXParseException parse && parse.getLineNumber() > 0) {
				if (declaresDoctype(parse)) {
					return where(file, parse) + ": " + DOCTYPE_REFUSED;
				}
				return where(file, parse) + ": not a statechart model: " + xmlMessage(parse);
			}
			if (cause instanceof Resource.Diagnostic diagnostic && diagnostic.getLine() > 0) {
				return file + ":" + diagnostic.getLine() + ":" + Math.max(diagnostic.getColumn(), 1) + ": not a statechart model: " + userText(diagnostic.getMessage());
			}
			if (cause instanceof NumberFormatException number) {
				java.util.regex.Matcher input = java.util.regex.Pattern.compile("For input string: \"(.*)\"").matcher(String.valueOf(number.getMessage()));
				String text = input.find() ? input.group(1) : "";
				return file + position(file, text) + ": not a statechart model: the number or reference " + quote(text) + " is malformed";
			}
		}
		Throwable root = e;
		while (root.getCause() != null && root.getCause() != root) {
			root = root.getCause();
		}
		return file + ": not a statechart model (" + (root instanceof ClassCastException ? "an element or a reference of the wrong kind" : userText(rootCause(e))) + ")";
	}

	/** Input text in a message: short, and without control characters that would garble the terminal. */
	private static String quote(String text) {
		String shown = text.length() > 60 ? text.substring(0, 60) + "…" : text;
		return "'" + shown.codePoints().map(c -> Character.isISOControl(c) || c == 0xfffd ? '?' : c)
				.collect(StringBuilder::new, StringBuilder::appendCodePoint, StringBuilder::append) + "'";
	}

	/** ":line:column" of the first occurrence of a text in the file, or nothing when it cannot be found. */
	private static String position(Path file, String text) {
		try {
			String content = Files.readString(file, java.nio.charset.StandardCharsets.ISO_8859_1);
			int at = text.isEmpty() ? -1 : content.indexOf(text);
			if (at < 0) {
				return "";
			}
			int line = 1;
			int lineStart = 0;
			for (int i = 0; i < at; i++) {
				if (content.charAt(i) == '\n') {
					line++;
					lineStart = i + 1;
				}
			}
			return ":" + line + ":" + (at - lineStart + 1);
		} catch (IOException unreadable) {
			return "";
		}
	}

	/** "file:line:column" of an XML parser's error. */
	public static String where(Path file, SAXParseException e) {
		return file + (e.getLineNumber() > 0 ? ":" + e.getLineNumber() + ":" + Math.max(e.getColumnNumber(), 1) : "");
	}

	/** An XML parser's message in a user's terms: without the JDK's message codes and property names. */
	public static String xmlMessage(SAXException e) {
		String message = String.valueOf(e.getMessage());
		if (message.startsWith("Content is not allowed in prolog")) {
			return "the file is not XML (a model file begins with <?xml or <statechart:Model)";
		}
		if (message.contains("maxElementDepth")) {
			return "the XML nests elements deeper than " + MAX_ELEMENT_DEPTH + ", which KSE does not read";
		}
		if (declaresDoctype(e)) {
			return "it declares a DOCTYPE (KSE files have none)";
		}
		return userText(message.replaceFirst("^JAXP\\d+: ", "").replaceAll("\\s*set by \"jdk\\.xml\\.\\w+\"\\.?", ""));
	}

	/**
	 * Whether the parser refused a DOCTYPE because {@value #DISALLOW_DOCTYPE} is set: the JDK's
	 * message names the feature in every language it is translated into.
	 */
	private static boolean declaresDoctype(SAXException e) {
		return String.valueOf(e.getMessage()).contains(DISALLOW_DOCTYPE);
	}

	/** A library's message without Java in it (class names, object identities). */
	private static String userText(String message) {
		return message == null ? "" : message.replaceFirst(" \\((file|platform):[^()]*, \\d+, \\d+\\)$", "").replaceAll("\\b(?:[a-z]\\w*\\.)+([A-Z]\\w*)(?:Impl)?@[0-9a-f]+", "$1").replaceAll("\\b(?:java|javax|org|com)\\.(?:\\w+\\.)+(\\w+)", "$1");
	}

	private static String rootCause(Throwable e) {
		Throwable cause = e;
		while (cause.getCause() != null && cause.getCause() != cause) {
			cause = cause.getCause();
		}
		String message = cause.getMessage();
		return message == null ? cause.getClass().getSimpleName() : message;
	}
}
