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
import java.util.Map;
import java.util.UUID;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.resource.impl.FileURIHandlerImpl;
import org.eclipse.emf.ecore.resource.impl.PlatformResourceURIHandlerImpl;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.emf.ecore.xmi.XMLResource;
import org.eclipse.emf.ecore.xmi.impl.XMIResourceFactoryImpl;
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
		resourceSet.getResourceFactoryRegistry().getExtensionToFactoryMap().put(FILE_EXTENSION, new XMIResourceFactoryImpl());
		resourceSet.getResourceFactoryRegistry().getExtensionToFactoryMap().put("*", new XMIResourceFactoryImpl());
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
		checkReadable(file);
		Resource resource = resourceSet.createResource(URI.createFileURI(file.toAbsolutePath().toString()));
		try {
			resource.load(loadOptions());
		} catch (IOException | RuntimeException e) {
			throw new IOException(file + ": not a statechart model (" + rootCause(e) + ")", e);
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
		ByteArrayOutputStream bytes = new ByteArrayOutputStream();
		resource.save(bytes, saveOptions());
		Path target = Path.of(resource.getURI().toFileString());
		writeAtomically(target, bytes.toByteArray());
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
		ByteArrayOutputStream bytes = new ByteArrayOutputStream();
		if (model.eResource() != null) {
			model.eResource().save(bytes, saveOptions());
			return bytes.toByteArray();
		}
		Resource scratch = newResourceSet().createResource(URI.createFileURI("model.stct"));
		scratch.getContents().add(model);
		try {
			scratch.save(bytes, saveOptions());
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
		Path directory = target.toAbsolutePath().getParent();
		Files.createDirectories(directory);
		Path temporary = directory.resolve("." + target.getFileName() + "." + UUID.randomUUID() + ".tmp");
		try {
			Files.write(temporary, content, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
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

	private static Map<Object, Object> loadOptions() {
		Map<Object, Object> options = new HashMap<>();
		options.put(XMLResource.OPTION_DEFER_IDREF_RESOLUTION, Boolean.TRUE);
		// The JDK's parser refuses elements nested deeper than 100, but KSE writes deeper models
		// (a formula nests its terms): every model KSE saves must load again. Set on this
		// parser only, not for the whole JVM.
		options.put(XMLResource.OPTION_PARSER_PROPERTIES, Map.of("jdk.xml.maxElementDepth", String.valueOf(MAX_ELEMENT_DEPTH)));
		return options;
	}

	private static Map<Object, Object> saveOptions() {
		Map<Object, Object> options = new HashMap<>();
		// the original tool's files are ASCII with character references; keep that
		options.put(XMLResource.OPTION_ENCODING, "ASCII");
		options.put(XMLResource.OPTION_SAVE_TYPE_INFORMATION, Boolean.FALSE);
		return options;
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
