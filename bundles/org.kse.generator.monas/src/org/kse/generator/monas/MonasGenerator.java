package org.kse.generator.monas;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.Diagnostic;
import org.kse.expression.ExpressionParser;
import org.kse.messages.MessageCatalog;
import org.kse.messages.ProtoProblem;
import org.kse.messages.StandardMessages;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.validation.ModelValidation;

/**
 * Writes the Monas C++ of a statechart into a source folder (docs/original-kse.md §7):
 * {@code statecharts/<Model>/} is owned by the generator and rewritten as needed;
 * {@code activities/<Activity>/} is the user's: created once, never overwritten.
 * A file whose content would not change is not touched, so builds stay incremental.
 */
public final class MonasGenerator {

	/**
	 * Generation settings. {@code logger}: conditions print their result.
	 * {@code messageFolders}: folders of the user's own .proto files, besides the source
	 * folder's {@code messages/} that is always read. {@code activities}: whether skeletons of
	 * new activities are written; a build that generates the statechart into its build tree
	 * (CMake's kse_add_statechart) keeps the activities in the source tree, so it writes none.
	 * {@code statechart}: whether the statechart's files are written; such a project asks for the
	 * skeletons of its new activities alone.
	 */
	public record Options(boolean logger, List<Path> messageFolders, boolean activities, boolean statechart) {
		public static final Options DEFAULT = new Options(false, List.of());

		public Options(boolean logger, List<Path> messageFolders, boolean activities) {
			this(logger, messageFolders, activities, true);
		}

		public Options(boolean logger) {
			this(logger, List.of());
		}

		public Options(boolean logger, List<Path> messageFolders) {
			this(logger, messageFolders, true);
		}
	}

	/** The folder of a source tree that holds the user's own .proto files. */
	public static final String MESSAGES_FOLDER = "messages";

	/**
	 * What a generation did, by path relative to the source folder; which standard messages the
	 * tree's own .proto files replaced; and warnings worded as diagnostics ({@code label (name): message}).
	 */
	public record Report(List<Path> written, List<Path> unchanged, List<Path> kept, List<Path> removed,
			List<StandardMessages.Replacement> replacements, List<String> warnings, List<ProtoProblem> messageProblems) {
	}

	/** Reports each step of a long generation: step of total, and what it is doing. */
	@FunctionalInterface
	public interface Progress {
		Progress NONE = (step, total, what) -> {
		};

		void step(int step, int total, String what);
	}

	/** The model has errors; nothing was written. */
	public static final class ModelHasErrorsException extends Exception {
		private static final long serialVersionUID = 1L;
		private final List<String> errors;

		ModelHasErrorsException(List<String> errors) {
			super("the model has " + errors.size() + (errors.size() == 1 ? " error" : " errors") + ": " + String.join("; ", errors));
			this.errors = List.copyOf(errors);
		}

		public List<String> errors() {
			return errors;
		}
	}

	private MonasGenerator() {
	}

	public static Report generate(Model model, Path sourceFolder, Options options) throws IOException, ModelHasErrorsException {
		return generate(model, sourceFolder, options, Progress.NONE);
	}

	public static Report generate(Model model, Path sourceFolder, Options options, Progress progress)
			throws IOException, ModelHasErrorsException {
		progress.step(1, 3, "validating " + model.getName());
		Path root = sourceFolder.toAbsolutePath().normalize();
		if (Files.exists(root) && !Files.isDirectory(root)) {
			throw new IOException(sourceFolder + ": not a folder (generate writes into a source folder)");
		}
		List<Path> messageFolders = new ArrayList<>(options.messageFolders());
		messageFolders.add(root.resolve(MESSAGES_FOLDER));
		StandardMessages.Merged messages = StandardMessages.merge(messageFolders);
		MessageCatalog catalog = messages.catalog();
		// One parse of each expression for the whole run: the validation's, reused by the plan and the runtime check.
		ExpressionParser.Session expressions = ExpressionParser.session();
		List<String> errors = new ArrayList<>();
		for (Diagnostic diagnostic : ModelValidation.validate(model, catalog, expressions).getChildren()) {
			if (diagnostic.getSeverity() == Diagnostic.ERROR) {
				errors.add(diagnostic.getMessage());
			}
		}
		if (!errors.isEmpty()) {
			throw new ModelHasErrorsException(errors);
		}
		progress.step(2, 3, "planning the C++ of " + model.getName());
		GenerationPlan plan = GenerationPlan.of(model, catalog, TreeMessages.of(root.resolve(MESSAGES_FOLDER), messages.replacements()), expressions);
		if (!plan.problems().isEmpty()) {
			throw new ModelHasErrorsException(plan.problems());
		}
		// Everything is rendered before the first write, so a failure leaves the tree as it was.
		Map<Path, String> owned = new LinkedHashMap<>();
		Path chart = Path.of("statecharts", plan.className());
		owned.put(chart.resolve(plan.className() + ".h"), MonasTemplates.statechartHeader(plan));
		owned.put(chart.resolve(plan.className() + ".cpp"), MonasTemplates.statechartSource(plan));
		owned.put(chart.resolve("CMakeLists.txt"), MonasTemplates.statechartCmake(plan));
		for (GenerationPlan.PlannedTransition transition : plan.transitions()) {
			if (transition.condition() != null) {
				owned.put(chart.resolve("transitions").resolve(transition.conditionClass() + ".h"),
						MonasTemplates.condition(plan, transition, options.logger()));
			}
			if (transition.action() != null && !MonasTemplates.timeoutOnly(transition.action())) {
				owned.put(chart.resolve("transitions").resolve(transition.actionClass() + ".h"), MonasTemplates.action(plan, transition));
			}
		}
		// null for an activity the user already has: it is never written, so it is not rendered either.
		Map<String, Map<String, String>> newActivities = new LinkedHashMap<>();
		for (Map.Entry<String, Node> activity : options.activities() ? plan.activities().entrySet() : Set.<Map.Entry<String, Node>>of()) {
			String name = activity.getKey();
			if (usersActivity(root, Path.of("activities", name))) {
				newActivities.put(name, null);
				continue;
			}
			var inputs = activity.getValue().getVariables().stream().filter(v -> v.getType() != null && v.getType().split("\\.").length == 3).toList();
			Map<String, String> files = new LinkedHashMap<>();
			files.put(name + ".h", MonasTemplates.activityHeader(plan, name, inputs));
			files.put(name + ".cpp", MonasTemplates.activitySource(name, inputs));
			files.put("CMakeLists.txt", MonasTemplates.activityCmake(plan, name, inputs));
			newActivities.put(name, files);
		}
		progress.step(3, 3, "writing into " + root);
		List<Path> written = new ArrayList<>();
		List<Path> unchanged = new ArrayList<>();
		List<Path> kept = new ArrayList<>();
		List<Path> removed = new ArrayList<>();
		if (options.statechart()) {
			for (Map.Entry<Path, String> file : owned.entrySet()) {
				(write(root, file.getKey(), file.getValue()) ? written : unchanged).add(file.getKey());
			}
			removeStale(root, chart.resolve("transitions"), owned, removed);
			removeInterruptedWrites(root, chart);
			removeInterruptedWrites(root, chart.resolve("transitions"));
		}
		removeAbandonedStaging(root);
		for (Map.Entry<String, Map<String, String>> activity : newActivities.entrySet()) {
			Path folder = Path.of("activities", activity.getKey());
			if (activity.getValue() != null && createActivity(root, folder, activity.getValue())) {
				activity.getValue().keySet().forEach(file -> written.add(folder.resolve(file)));
			} else {
				kept.add(folder);
			}
		}
		return new Report(written, unchanged, kept, removed, messages.replacements(), runtimeMismatches(model, messageFolders, messages, expressions),
				messages.problems());
	}

	/** Where an activity's files are assembled before the folder appears under its own name in one step. */
	private static final String STAGING = ".kse-staging-";

	/**
	 * Creates an activity's folder with all its files, or leaves an existing one alone (it is the
	 * user's). The files are written into a hidden folder that is then renamed, so a run that is
	 * killed never leaves a half-made activity that later runs would take for the user's.
	 */
	private static boolean createActivity(Path root, Path relative, Map<String, String> files) throws IOException {
		Path folder = inside(root, relative);
		Path staging = inside(root, relative.resolveSibling(STAGING + relative.getFileName()));
		if (Files.exists(folder, LinkOption.NOFOLLOW_LINKS)) {
			if (usersActivity(root, relative)) {
				return false;
			}
			// Left by a generator before activities were staged, killed before it wrote a file.
			deleteStaging(folder);
		}
		Files.createDirectories(staging);
		for (Map.Entry<String, String> file : files.entrySet()) {
			Files.writeString(staging.resolve(file.getKey()), file.getValue(), StandardCharsets.UTF_8, StandardOpenOption.CREATE_NEW,
					StandardOpenOption.WRITE);
		}
		try {
			Files.move(staging, folder, StandardCopyOption.ATOMIC_MOVE);
		} catch (AtomicMoveNotSupportedException e) {
			Files.move(staging, folder);
		}
		return true;
	}

	/** An activity folder that exists with more in it than a killed run's temporary files: the user's. */
	private static boolean usersActivity(Path root, Path relative) throws IOException {
		Path folder = inside(root, relative);
		return Files.exists(folder, LinkOption.NOFOLLOW_LINKS) && !onlyInterruptedWrites(folder);
	}

	/** Activities a killed run was assembling. */
	private static void removeAbandonedStaging(Path root) throws IOException {
		Path activities = inside(root, Path.of("activities"));
		if (!Files.isDirectory(activities, LinkOption.NOFOLLOW_LINKS)) {
			return;
		}
		try (Stream<Path> folders = Files.list(activities)) {
			for (Path folder : folders.filter(f -> f.getFileName().toString().startsWith(STAGING)).toList()) {
				deleteStaging(folder);
			}
		}
	}

	/** True for a folder that holds nothing but temporary files of interrupted atomic writes. */
	private static boolean onlyInterruptedWrites(Path folder) throws IOException {
		if (!Files.isDirectory(folder, LinkOption.NOFOLLOW_LINKS)) {
			return false;
		}
		try (Stream<Path> files = Files.list(folder)) {
			return files.allMatch(MonasGenerator::isInterruptedWrite);
		}
	}

	private static boolean isInterruptedWrite(Path file) {
		String name = file.getFileName().toString();
		return name.startsWith(".") && name.endsWith(".tmp") && Files.isRegularFile(file, LinkOption.NOFOLLOW_LINKS);
	}

	/** Deletes a folder of KSE's own making (staging, or one holding only temporary files); no links are followed. */
	private static void deleteStaging(Path folder) throws IOException {
		if (!Files.isDirectory(folder, LinkOption.NOFOLLOW_LINKS)) {
			return;
		}
		try (Stream<Path> files = Files.list(folder)) {
			for (Path file : files.toList()) {
				Files.delete(file);
			}
		}
		Files.delete(folder);
	}

	/** Temporary files that a killed run's atomic writes left in a folder the generator owns. */
	private static void removeInterruptedWrites(Path root, Path relative) throws IOException {
		Path folder = inside(root, relative);
		if (!Files.isDirectory(folder, LinkOption.NOFOLLOW_LINKS)) {
			return;
		}
		try (Stream<Path> files = Files.list(folder)) {
			for (Path file : files.filter(MonasGenerator::isInterruptedWrite).toList()) {
				Files.delete(file);
			}
		}
	}

	private static final Pattern DIAGNOSTIC = Pattern.compile("(?s)(.*?\\): )(expression \\d+:\\d+: )?(.*)");

	/**
	 * What holds against the tree's own definition of a standard message but not against the
	 * runtime's, which the generated C++ is compiled with (see {@link TreeMessages}): that C++
	 * would not compile, and saying so now beats a compiler error about protobuf accessors.
	 */
	private static List<String> runtimeMismatches(Model model, List<Path> folders, StandardMessages.Merged messages,
			ExpressionParser.Session expressions) {
		if (messages.replacements().isEmpty()) {
			return List.of();
		}
		Set<Path> replacing = new HashSet<>();
		messages.replacements().forEach(replacement -> replacing.add(replacement.file().toAbsolutePath().normalize()));
		MessageCatalog runtime = StandardMessages.merge(folders, replacing).catalog();
		List<String> warnings = new ArrayList<>();
		for (Diagnostic diagnostic : ModelValidation.validate(model, runtime, expressions).getChildren()) {
			if (diagnostic.getSeverity() == Diagnostic.ERROR) {
				Matcher parts = DIAGNOSTIC.matcher(diagnostic.getMessage());
				warnings.add(parts.matches() ? parts.group(1) + (parts.group(2) == null ? "" : parts.group(2)) + "the generated C++ will not compile: "
						+ parts.group(3) + " in the KSE runtime's messages, which it is built with" : diagnostic.getMessage());
			}
		}
		return warnings;
	}

	/** Writes only when the content differs; true when the file was written. */
	private static boolean write(Path root, Path relative, String content) throws IOException {
		Path target = inside(root, relative);
		byte[] bytes = content.getBytes(StandardCharsets.UTF_8);
		if (Files.isRegularFile(target) && Arrays.equals(Files.readAllBytes(target), bytes)) {
			return false;
		}
		StatechartResources.writeAtomically(target, bytes);
		return true;
	}

	/** Transition classes of earlier generations that the model no longer has. */
	private static void removeStale(Path root, Path transitions, Map<Path, String> owned, List<Path> removed) throws IOException {
		Path folder = inside(root, transitions);
		if (!Files.isDirectory(folder)) {
			return;
		}
		try (Stream<Path> files = Files.list(folder)) {
			for (Path file : files.sorted().toList()) {
				String name = file.getFileName().toString();
				Path relative = transitions.resolve(name);
				if ((name.startsWith("TrCond_") || name.startsWith("TrAction_")) && name.endsWith(".h") && !owned.containsKey(relative)) {
					Files.delete(file);
					removed.add(relative);
				}
			}
		}
	}

	/**
	 * A path under the source folder; anything that would leave it is refused, also through a
	 * symbolic link (a shared tree could link {@code statecharts} to a folder of the victim's).
	 */
	static Path inside(Path root, Path relative) throws IOException {
		Path resolved = root.resolve(relative).normalize();
		if (!resolved.startsWith(root) || resolved.equals(root)) {
			throw new IOException("refusing to write outside " + root + ": " + relative);
		}
		if (Files.exists(root)) {
			Path realRoot = root.toRealPath();
			Path existing = resolved;
			while (!Files.exists(existing, LinkOption.NOFOLLOW_LINKS)) {
				existing = existing.getParent();
			}
			Path real;
			try {
				real = existing.toRealPath();
			} catch (NoSuchFileException e) {
				throw new IOException("refusing to write through " + existing + ": a symbolic link to nothing");
			}
			if (!real.startsWith(realRoot)) {
				throw new IOException("refusing to write outside " + root + ": " + root.relativize(existing) + " is a symbolic link to " + real);
			}
		}
		return resolved;
	}
}
