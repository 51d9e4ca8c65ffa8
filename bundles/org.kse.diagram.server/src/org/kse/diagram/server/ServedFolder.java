package org.kse.diagram.server;

import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The one folder whose statecharts a diagram server may open (the workspace, or the folder of
 * {@code kse serve}). A requested path is refused, with a message, when it leaves the folder
 * ({@code ../}, an absolute path elsewhere, a link out of it) or is not a {@code .stct} file.
 */
public final class ServedFolder {

	private final Path root;

	public ServedFolder(Path root) {
		this.root = root.toAbsolutePath().normalize();
	}

	public Path root() {
		return root;
	}

	/** The model file a client asks for, relative to the folder (or a file: URI or absolute path inside it). */
	public Path resolve(String requested) {
		if (requested == null || requested.isBlank()) {
			throw new IllegalArgumentException("no model file was named");
		}
		String path = requested.startsWith("file://") ? java.net.URI.create(requested).getPath() : requested;
		if (path.contains("\0")) {
			throw new IllegalArgumentException("refused: " + requested + " is not a file name");
		}
		for (String segment : path.replace('\\', '/').split("/")) {
			if (segment.equals("..")) {
				throw new IllegalArgumentException("refused: " + requested + " leaves the served folder");
			}
		}
		Path file = root.resolve(path).normalize();
		if (!file.startsWith(root)) {
			throw new IllegalArgumentException("refused: " + requested + " is outside the served folder");
		}
		if (!file.getFileName().toString().endsWith(".stct")) {
			throw new IllegalArgumentException("refused: " + requested + " is not a statechart (.stct)");
		}
		try {
			if (Files.exists(file) && !file.toRealPath().startsWith(root.toRealPath())) {
				throw new IllegalArgumentException("refused: " + requested + " links outside the served folder");
			}
		} catch (java.io.IOException e) {
			throw new IllegalArgumentException("cannot open " + requested + ": " + e.getMessage(), e);
		}
		return file;
	}
}
