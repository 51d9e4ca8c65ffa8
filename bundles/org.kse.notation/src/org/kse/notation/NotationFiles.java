package org.kse.notation;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import com.google.gson.JsonParseException;

/**
 * The notation file beside a model ({@code Goalie.notation.json} for {@code Goalie.stct}), written
 * atomically; and opening a model's notation from the best source there is: that file, else the
 * original tool's {@code .kse} diagram, else a new arrangement.
 */
public final class NotationFiles {

	/** Where an opened notation came from. */
	public enum Source {
		SIDECAR, LEGACY_DIAGRAM, ARRANGED
	}

	/** A notation as opened; {@code problem} says why a file beside the model could not be used. */
	public record Opened(Notation notation, Source source, String problem) {
	}

	private static final Gson GSON = new GsonBuilder().setPrettyPrinting().disableHtmlEscaping().create();
	private static final int FORMAT = 1;

	private record Document(int format, String model, java.util.List<Notation.Entry> states) {
	}

	private NotationFiles() {
	}

	public static Path beside(Path modelFile) {
		String name = modelFile.getFileName().toString();
		return modelFile.resolveSibling(name.replaceFirst("\\.stct$", "") + ".notation.json");
	}

	public static void write(Path modelFile, Model model, Notation notation) throws IOException {
		String json = GSON.toJson(new Document(FORMAT, model.getName(), java.util.List.copyOf(notation.entries())));
		StatechartResources.writeAtomically(beside(modelFile), (json + "\n").getBytes(StandardCharsets.UTF_8));
	}

	public static Notation read(Path notationFile) throws IOException {
		try {
			Document document = GSON.fromJson(Files.readString(notationFile, StandardCharsets.UTF_8), Document.class);
			if (document == null || document.states() == null) {
				throw new IOException(notationFile + ": not a KSE notation file (no states)");
			}
			if (document.format() > FORMAT) {
				throw new IOException(notationFile + ": written by a newer KSE (format " + document.format() + ")");
			}
			Notation notation = new Notation();
			for (Notation.Entry entry : document.states()) {
				if (entry == null || entry.element() == null || entry.bounds() == null) {
					throw new IOException(notationFile + ": a state without its path or bounds");
				}
				notation.put(entry);
			}
			return notation;
		} catch (JsonParseException e) {
			throw new IOException(notationFile + ": not valid JSON: " + e.getMessage(), e);
		}
	}

	/**
	 * The notation of a model: its notation file, else the original's diagram, else arranged.
	 * States the file does not place (added since) are placed by a new arrangement; a file that
	 * cannot be read is reported in {@link Opened#problem()} and the model is arranged anew.
	 */
	public static Opened open(Path modelFile, Model model) {
		String problem = null;
		Path sidecar = beside(modelFile);
		try {
			if (Files.isRegularFile(sidecar)) {
				return new Opened(complete(read(sidecar), model), Source.SIDECAR, null);
			}
			if (LegacyNotation.exists(modelFile)) {
				return new Opened(complete(LegacyNotation.read(LegacyNotation.beside(modelFile), model), model), Source.LEGACY_DIAGRAM, null);
			}
		} catch (IOException e) {
			problem = e.getMessage();
		}
		return new Opened(Arrange.all(model), Source.ARRANGED, problem);
	}

	private static Notation complete(Notation notation, Model model) {
		if (notation.covers(model)) {
			return notation;
		}
		Notation arranged = Arrange.all(model);
		for (var contents = model.eAllContents(); contents.hasNext();) {
			if (contents.next() instanceof org.kse.model.statechart.Node node && notation.get(node) == null) {
				notation.put(node, arranged.get(node));
			}
		}
		return notation;
	}
}
