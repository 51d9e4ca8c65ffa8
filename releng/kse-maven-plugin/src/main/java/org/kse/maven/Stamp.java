package org.kse.maven;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.stream.Stream;

/**
 * What the last successful run of a goal saw, kept under {@code target/kse/}: one line per
 * input (the plugin and the KSE jars it runs, the options, a SHA-256 of every model and of every
 * .proto file the command reads) and one per output (a SHA-256 of every generated file). The
 * next run starts the command only when an input line differs, or an output is missing or was
 * changed by hand. Contents, not modification times: a checkout or a copy that touches every
 * file must not regenerate, an edit that keeps the time must.
 */
final class Stamp {

	private static final String OUTPUT = "output ";

	private final List<String> inputs = new ArrayList<>();

	void input(String kind, String value) {
		inputs.add(kind + " " + value);
	}

	void file(String kind, Path file) throws IOException {
		inputs.add(kind + " " + sha256(file) + " " + file);
	}

	/** Every *.proto under the folder, as the command reads them (a missing folder is none). */
	void protos(Path folder) throws IOException {
		input("messages-folder", folder.toString());
		if (!Files.isDirectory(folder)) {
			return;
		}
		try (Stream<Path> walk = Files.walk(folder)) {
			for (Path proto : walk.filter(p -> p.toString().endsWith(".proto") && Files.isRegularFile(p)).sorted().toList()) {
				file("proto", proto);
			}
		}
	}

	/**
	 * True when the stamp holds exactly these inputs and every output it lists is still there
	 * with the content the command wrote.
	 */
	boolean matches(Path stampFile, boolean needsOutputs) throws IOException {
		List<String> lines;
		try {
			lines = Files.readAllLines(stampFile, StandardCharsets.UTF_8);
		} catch (NoSuchFileException e) {
			return false;
		}
		List<String> recordedInputs = new ArrayList<>();
		List<String> outputs = new ArrayList<>();
		for (String line : lines) {
			if (line.startsWith("#")) {
				continue;
			}
			(line.startsWith(OUTPUT) ? outputs : recordedInputs).add(line);
		}
		if (!recordedInputs.equals(inputs) || (needsOutputs && outputs.isEmpty())) {
			return false;
		}
		for (String output : outputs) {
			String[] parts = output.substring(OUTPUT.length()).split(" ", 2);
			if (parts.length != 2) {
				return false;
			}
			Path file = Path.of(parts[1]);
			if (!Files.isRegularFile(file) || !sha256(file).equals(parts[0])) {
				return false;
			}
		}
		return true;
	}

	void write(Path stampFile, String header, List<Path> outputs) throws IOException {
		StringBuilder text = new StringBuilder("# ").append(header).append('\n');
		for (String input : inputs) {
			text.append(input).append('\n');
		}
		for (Path output : outputs) {
			text.append(OUTPUT).append(sha256(output)).append(' ').append(output).append('\n');
		}
		Files.createDirectories(stampFile.getParent());
		Path temporary = stampFile.resolveSibling(stampFile.getFileName() + ".tmp");
		Files.writeString(temporary, text, StandardCharsets.UTF_8);
		try {
			Files.move(temporary, stampFile, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
		} catch (AtomicMoveNotSupportedException e) {
			Files.move(temporary, stampFile, StandardCopyOption.REPLACE_EXISTING);
		}
	}

	static String sha256(Path file) throws IOException {
		MessageDigest digest;
		try {
			digest = MessageDigest.getInstance("SHA-256");
		} catch (NoSuchAlgorithmException e) {
			throw new IllegalStateException("every Java has SHA-256", e);
		}
		byte[] buffer = new byte[64 * 1024];
		try (InputStream in = Files.newInputStream(file)) {
			for (int read; (read = in.read(buffer)) > 0;) {
				digest.update(buffer, 0, read);
			}
		}
		return HexFormat.of().formatHex(digest.digest());
	}
}
