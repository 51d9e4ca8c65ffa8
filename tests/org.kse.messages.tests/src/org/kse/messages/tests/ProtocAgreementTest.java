package org.kse.messages.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.EnumMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Random;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kse.messages.EnumType;
import org.kse.messages.MessageCatalog;
import org.kse.messages.MessageType;
import org.kse.messages.ProtoFile;
import org.kse.messages.ProtoImport;
import org.kse.messages.ProtoReader;
import org.kse.messages.ProtoProblem;

/**
 * Differential test of KSE's {@code .proto} reader against the real peer, {@code protoc} (ADR 0019).
 * <ol>
 * <li>Every {@code .proto} file of the repository is accepted by both, and both list the same
 * message types (nested ones as {@code Outer.Inner}) with the same field names and numbers, and the
 * same enums with the same values. protoc's view is its descriptor set
 * ({@code --descriptor_set_out --include_imports}), read by the small wire-format reader below.</li>
 * <li>Seeded mutants of those files: KSE reports a problem exactly when protoc exits non-zero.</li>
 * </ol>
 * protoc runs as a local process (no network) with a timeout. Without {@code protoc} on the PATH
 * the tests are skipped, visibly; CI installs it (releng/debian-packages.sh).
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class ProtocAgreementTest {

	/** Fixed, so that every run sees the same variants; printed, and overridable to explore. */
	private static final long SEED = Long.getLong("kse.protocAgreement.seed", 0x4B5E_0019L);

	private static final int VARIANTS_PER_FILE = 220;

	/** Imports of the runtime's messages are written as protoc sees the installed files. */
	private static final String RUNTIME_IMPORT_PREFIX = "kse/messages/";

	private static final long PROTOC_TIMEOUT_SECONDS = 20;

	private static Path protoc;

	@TempDir
	Path tmp;

	@BeforeAll
	static void findProtoc() {
		protoc = onPath("protoc").orElse(null);
		Assumptions.assumeTrue(protoc != null,
				"protoc is not on the PATH (Debian package protobuf-compiler): the differential test against it is SKIPPED");
	}

	// ---- 1. the real files

	@Test
	void realFilesAreAcceptedByBothWithTheSameTypesAndFields() throws Exception {
		List<RealFile> files = realFiles(tmp.resolve("imports"));
		System.out.println("ProtocAgreementTest: " + files.size() + " real .proto files, protoc " + protocVersion());
		for (RealFile real : files) {
			Path out = tmp.resolve("descriptors").resolve(real.name() + ".pb");
			Files.createDirectories(out.getParent());
			Protoc result = runProtoc(real.file(), real.importRoot(), out, true);
			assertEquals(0, result.exit(), () -> "protoc refuses " + real.file() + ":\n" + result.output());

			MessageCatalog catalog = kseCatalog(real, Files.readString(real.file()));
			assertTrue(catalog.problems().isEmpty(), () -> "KSE refuses " + real.file() + ":\n" + problems(catalog));

			Map<String, List<String>> expected = Descriptors.types(Files.readAllBytes(out));
			Map<String, List<String>> actual = kseTypes(catalog);
			assertFalse(expected.isEmpty(), () -> "protoc lists no types for " + real.file());
			assertEquals(format(expected), format(actual), () -> "types of " + real.file() + " (with its imports)");
		}
	}

	// ---- 2. seeded mutants

	/**
	 * The mutations. Each is applied once to one real file; tokens inside options ({@code [...]} and
	 * {@code option ...;}) are never chosen, see {@link Mutant#pickable}.
	 */
	enum Kind {
		DELETE_TOKEN, DUPLICATE_LINE, SWAP_ADJACENT_TOKENS, DROP_SEMICOLON, FIELD_NUMBER_ZERO, FIELD_NUMBER_DUPLICATE,
		FIELD_NUMBER_EDGE, FIELD_NAME_DUPLICATE, TYPE_UNKNOWN, LABEL_CHANGE, INSERT_TOKEN
	}

	/**
	 * The kinds on which KSE must agree with protoc, i.e. all of them. Were a kind ever left out it
	 * would still run and print its disagreements, but not fail the test.
	 */
	private static final Set<Kind> ENFORCED = Set.of(Kind.values());

	@Test
	void mutantsAreRefusedByKseExactlyWhenProtocRefusesThem() throws Exception {
		List<RealFile> files = realFiles(tmp.resolve("imports"));
		Random random = new Random(SEED);
		List<Variant> variants = new ArrayList<>();
		for (RealFile real : files) {
			String text = Files.readString(real.file());
			Set<String> seen = new HashSet<>(Set.of(text));
			for (int attempts = 0, made = 0; made < VARIANTS_PER_FILE && attempts < VARIANTS_PER_FILE * 20; attempts++) {
				Kind kind = Kind.values()[random.nextInt(Kind.values().length)];
				Optional<Variant> v = Mutant.apply(real, text, kind, random);
				if (v.isPresent() && seen.add(v.get().text())) {
					variants.add(v.get());
					made++;
				}
			}
		}
		System.out.println("ProtocAgreementTest: seed " + SEED + " (-Dkse.protocAgreement.seed=...), "
				+ variants.size() + " variants of " + files.size() + " files");

		ExecutorService pool = Executors.newFixedThreadPool(Math.max(2, Runtime.getRuntime().availableProcessors()));
		List<Future<Verdicts>> futures = new ArrayList<>();
		try {
			for (int i = 0; i < variants.size(); i++) {
				Variant v = variants.get(i);
				Path dir = tmp.resolve("variants").resolve(String.valueOf(i));
				futures.add(pool.submit(() -> judge(v, dir)));
			}
			Map<Kind, int[]> counts = new EnumMap<>(Kind.class); // both accept, both refuse, disagree
			Map<Kind, List<String>> disagreements = new EnumMap<>(Kind.class);
			for (int i = 0; i < variants.size(); i++) {
				Variant v = variants.get(i);
				Verdicts verdicts = get(futures.get(i));
				int[] c = counts.computeIfAbsent(v.kind(), k -> new int[3]);
				if (verdicts.kseRefuses() == verdicts.protocRefuses()) {
					c[verdicts.kseRefuses() ? 1 : 0]++;
				} else {
					c[2]++;
					disagreements.computeIfAbsent(v.kind(), k -> new ArrayList<>()).add(describe(v, verdicts));
				}
			}
			String summary = summary(counts);
			System.out.println(summary);
			disagreements.forEach((kind, list) -> {
				System.out.println("---- " + list.size() + " disagreement(s) of " + kind
						+ (ENFORCED.contains(kind) ? "" : " (not enforced)"));
				list.stream().limit(10).forEach(System.out::println);
			});
			List<String> failing = disagreements.entrySet().stream().filter(e -> ENFORCED.contains(e.getKey()))
					.flatMap(e -> e.getValue().stream()).toList();
			assertTrue(failing.isEmpty(), () -> failing.size() + " variant(s) on which KSE and protoc disagree (seed "
					+ SEED + ")\n" + summary + "\n" + failing.stream().limit(20).collect(Collectors.joining("\n")));
			// A test that cannot fail proves nothing: both verdicts must actually occur, for every kind enforced.
			for (Kind kind : ENFORCED) {
				assertTrue(counts.containsKey(kind), () -> "no variant of kind " + kind);
			}
			assertTrue(counts.values().stream().mapToInt(c -> c[0]).sum() > 0, "no variant accepted by both");
			assertTrue(counts.values().stream().mapToInt(c -> c[1]).sum() > 0, "no variant refused by both");
		} finally {
			pool.shutdownNow();
		}
	}

	private record Verdicts(boolean kseRefuses, String kse, boolean protocRefuses, String protoc) {
	}

	private Verdicts judge(Variant v, Path dir) throws IOException, InterruptedException {
		Files.createDirectories(dir);
		Path file = Files.writeString(dir.resolve(v.real().name()), v.text());
		Protoc result = runProtoc(file, v.real().importRoot(), dir.resolve("out.pb"), false);
		MessageCatalog catalog = kseCatalog(v.real(), v.text());
		List<ProtoProblem> problems = catalog.problems();
		return new Verdicts(!problems.isEmpty(), problems.isEmpty() ? "accepts" : "refuses: " + problems.get(0).line()
				+ ":" + problems.get(0).column() + ": " + problems.get(0).message(), result.exit() != 0,
				result.exit() == 0 ? "accepts" : "refuses: " + firstLine(result.output().replace(dir + File.separator, "")));
	}

	private static String describe(Variant v, Verdicts verdicts) {
		String[] lines = v.text().split("\n", -1);
		StringBuilder s = new StringBuilder();
		s.append(v.real().name()).append(", ").append(v.kind()).append(": ").append(v.what()).append('\n');
		for (int l = Math.max(1, v.line() - 1); l <= Math.min(lines.length, v.line() + 1); l++) {
			s.append(String.format("  %4d | %s%n", l, lines[l - 1]));
		}
		s.append("  KSE ").append(verdicts.kse()).append("\n  protoc ").append(verdicts.protoc());
		return s.toString();
	}

	private static String summary(Map<Kind, int[]> counts) {
		StringBuilder s = new StringBuilder(String.format("%-22s %8s %8s %8s%n", "kind", "accept", "refuse", "DISAGREE"));
		int[] total = new int[3];
		counts.forEach((kind, c) -> {
			s.append(String.format("%-22s %8d %8d %8d%s%n", kind, c[0], c[1], c[2],
					ENFORCED.contains(kind) ? "" : "  (not enforced)"));
			for (int i = 0; i < 3; i++) {
				total[i] += c[i];
			}
		});
		s.append(String.format("%-22s %8d %8d %8d", "total", total[0], total[1], total[2]));
		return s.toString();
	}

	// ---- the files, KSE's view

	/**
	 * A real file, the folder protoc reads its imports from, and the files it imports (transitively,
	 * as KSE must be given them).
	 */
	private record RealFile(Path file, String name, Path importRoot, List<Path> imports) {
	}

	/** runtime/messages, examples and tests/data, staging the runtime's files as kse/messages/. */
	private static List<RealFile> realFiles(Path importRoot) throws IOException {
		Path repository = Path.of(System.getProperty("kse.repository", "../..")).toAbsolutePath().normalize();
		List<Path> found = new ArrayList<>();
		for (String folder : List.of("runtime", "examples", "tests/data")) {
			Path root = repository.resolve(folder);
			if (Files.isDirectory(root)) {
				try (Stream<Path> walk = Files.walk(root)) {
					walk.filter(p -> p.toString().endsWith(".proto") && Files.isRegularFile(p))
							.filter(p -> !isBuildOutput(root.relativize(p))).sorted().forEach(found::add);
				}
			}
		}
		assertTrue(found.stream().anyMatch(p -> p.startsWith(repository.resolve("runtime/messages"))),
				() -> "no .proto files in " + repository.resolve("runtime/messages") + " (kse.repository)");
		Path staged = importRoot.resolve(RUNTIME_IMPORT_PREFIX);
		Files.createDirectories(staged);
		for (Path p : found) {
			if (p.getParent().equals(repository.resolve("runtime/messages"))) {
				Files.copy(p, staged.resolve(p.getFileName().toString()));
			}
		}
		List<RealFile> result = new ArrayList<>();
		for (Path p : found) {
			result.add(new RealFile(p, p.getFileName().toString(), importRoot, importsOf(p, importRoot)));
		}
		return result;
	}

	private static boolean isBuildOutput(Path relative) {
		for (Path part : relative) {
			String s = part.toString();
			if (s.equals("target") || s.startsWith("build") || s.startsWith(".") || s.equals("node_modules")) {
				return true;
			}
		}
		return false;
	}

	/** The files {@code file} imports, directly or not, looked up as protoc does with -I its folder -I importRoot. */
	private static List<Path> importsOf(Path file, Path importRoot) throws IOException {
		List<Path> result = new ArrayList<>();
		Deque<Path> todo = new ArrayDeque<>(List.of(file));
		Set<Path> done = new HashSet<>();
		while (!todo.isEmpty()) {
			Path current = todo.pop();
			if (!done.add(current)) {
				continue;
			}
			if (!current.equals(file)) {
				result.add(current);
			}
			for (ProtoImport imp : ProtoReader.read(current, Files.readString(current)).imports()) {
				Path beside = file.getParent().resolve(imp.path());
				todo.push(Files.isRegularFile(beside) ? beside : importRoot.resolve(imp.path()));
			}
		}
		return result;
	}

	/** KSE's view of {@code text} standing for the real file, its imports parsed afresh (linking changes them). */
	private static MessageCatalog kseCatalog(RealFile real, String text) throws IOException {
		List<ProtoFile> files = new ArrayList<>();
		files.add(ProtoReader.read(real.file(), text));
		for (Path imported : real.imports()) {
			files.add(ProtoReader.read(imported, Files.readString(imported)));
		}
		return MessageCatalog.of(files);
	}

	/** "message pkg.Outer.Inner" -> ["name = number", ...]; "enum pkg.E" -> ["VALUE = number", ...]. */
	private static Map<String, List<String>> kseTypes(MessageCatalog catalog) {
		Map<String, List<String>> types = new TreeMap<>();
		for (MessageType m : catalog.messages()) {
			types.put("message " + m.fullName(), m.fields().stream().map(f -> f.name() + " = " + f.number()).toList());
		}
		for (EnumType e : catalog.enums()) {
			types.put("enum " + e.fullName(),
					e.values().entrySet().stream().map(v -> v.getKey() + " = " + v.getValue()).toList());
		}
		return types;
	}

	private static String format(Map<String, List<String>> types) {
		return types.entrySet().stream().map(e -> e.getKey() + " { " + String.join("; ", e.getValue()) + " }")
				.collect(Collectors.joining("\n"));
	}

	private static String problems(MessageCatalog catalog) {
		return catalog.problems().stream().map(ProtoProblem::toString).collect(Collectors.joining("\n"));
	}

	// ---- protoc

	private record Protoc(int exit, String output) {
	}

	private static Protoc runProtoc(Path file, Path importRoot, Path out, boolean includeImports)
			throws IOException, InterruptedException {
		List<String> command = new ArrayList<>(List.of(protoc.toString(), "--proto_path=" + file.getParent(),
				"--proto_path=" + importRoot, "--descriptor_set_out=" + out));
		if (includeImports) {
			command.add("--include_imports");
		}
		command.add(file.toString());
		Process process = new ProcessBuilder(command).directory(file.getParent().toFile()).redirectErrorStream(true)
				.start();
		process.getOutputStream().close();
		// protoc writes little; reading before waiting cannot dead-lock on a full pipe.
		String output = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
		if (!process.waitFor(PROTOC_TIMEOUT_SECONDS, TimeUnit.SECONDS)) {
			process.destroyForcibly();
			fail("protoc took more than " + PROTOC_TIMEOUT_SECONDS + " s on " + file);
		}
		return new Protoc(process.exitValue(), output);
	}

	private static String protocVersion() throws IOException, InterruptedException {
		Process process = new ProcessBuilder(protoc.toString(), "--version").redirectErrorStream(true).start();
		String output = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
		process.waitFor(PROTOC_TIMEOUT_SECONDS, TimeUnit.SECONDS);
		return output;
	}

	private static Optional<Path> onPath(String program) {
		String path = System.getenv("PATH");
		if (path == null) {
			return Optional.empty();
		}
		for (String dir : path.split(File.pathSeparator)) {
			for (String name : List.of(program, program + ".exe")) {
				Path candidate = Path.of(dir.isEmpty() ? "." : dir, name);
				if (Files.isRegularFile(candidate) && Files.isExecutable(candidate)) {
					return Optional.of(candidate);
				}
			}
		}
		return Optional.empty();
	}

	/** The first error protoc prints, or else its first line (warnings come first). */
	private static String firstLine(String s) {
		List<String> lines = s.strip().lines().toList();
		return lines.stream().filter(l -> !l.startsWith("[libprotobuf WARNING")).findFirst()
				.orElse(lines.isEmpty() ? "" : lines.get(0));
	}

	private static <T> T get(Future<T> future) throws InterruptedException {
		try {
			return future.get();
		} catch (ExecutionException e) {
			if (e.getCause() instanceof IOException io) {
				throw new UncheckedIOException(io);
			}
			throw new AssertionError(e.getCause());
		}
	}

	// ---- mutants

	/** One mutant: the kind, what was done, the 1-based line of the change. */
	private record Variant(RealFile real, Kind kind, String what, int line, String text) {
	}

	/** A token of the original text: [start, end) offsets, line, brace block, whether inside an option. */
	private record Tok(String text, int start, int end, int line, int block, boolean inOption) {

		boolean isIdent() {
			return Character.isJavaIdentifierStart(text.charAt(0));
		}

		boolean isInt() {
			return Character.isDigit(text.charAt(0));
		}
	}

	private static final class Mutant {

		private static final List<String> LABELS = List.of("optional", "required", "repeated", "");
		private static final List<String> EDGE_NUMBERS = List.of("-1", "18999", "19000", "19999", "20000", "536870911",
				"536870912", "2147483648", "0x10", "010", "09", "1.0");
		/**
		 * Tokens to insert. {@code reserved} and {@code extensions} too: the grammar parses those
		 * statements as protoc does (the hand-written reader skipped them up to their ';', so a
		 * malformed one such as {@code reserved optional int32 x = 1;} was not refused).
		 */
		private static final List<String> INSERTED = List.of(";", "{", "}", "=", "1", "x", "message", "enum", "optional",
				"int32", ".", ",", "<", ">", "\"s\"", "oneof", "map", "import", "package", "syntax", "-", "group", "reserved",
				"extensions");

		private final List<Tok> tokens = new ArrayList<>();

		private Mutant(String text) {
			tokenize(text);
		}

		static Optional<Variant> apply(RealFile real, String text, Kind kind, Random random) {
			Mutant m = new Mutant(text);
			List<Tok> pickable = m.tokens.stream().filter(Mutant::pickable).toList();
			List<Integer> fieldNumbers = m.fieldNumberIndexes();
			if (pickable.isEmpty()) {
				return Optional.empty();
			}
			switch (kind) {
			case DELETE_TOKEN -> {
				Tok t = pick(pickable, random);
				return Optional.of(new Variant(real, kind, "deleted '" + t.text() + "'", t.line(), splice(text, t, "")));
			}
			case DUPLICATE_LINE -> {
				String[] lines = text.split("\n", -1);
				List<Integer> code = new ArrayList<>();
				for (Tok t : pickable) {
					if (!code.contains(t.line())) {
						code.add(t.line());
					}
				}
				int line = pick(code, random);
				List<String> copy = new ArrayList<>(List.of(lines));
				copy.add(line, lines[line - 1]);
				return Optional.of(new Variant(real, kind, "duplicated line " + line, line + 1, String.join("\n", copy)));
			}
			case SWAP_ADJACENT_TOKENS -> {
				int i = m.tokens.indexOf(pick(pickable, random));
				if (i + 1 >= m.tokens.size() || !pickable(m.tokens.get(i + 1))
						|| m.tokens.get(i).text().equals(m.tokens.get(i + 1).text())) {
					return Optional.empty();
				}
				Tok a = m.tokens.get(i);
				Tok b = m.tokens.get(i + 1);
				String swapped = text.substring(0, a.start()) + b.text() + text.substring(a.end(), b.start()) + a.text()
						+ text.substring(b.end());
				return Optional.of(new Variant(real, kind, "swapped '" + a.text() + "' and '" + b.text() + "'", a.line(),
						swapped));
			}
			case DROP_SEMICOLON -> {
				List<Tok> semicolons = pickable.stream().filter(t -> t.text().equals(";")).toList();
				if (semicolons.isEmpty()) {
					return Optional.empty();
				}
				Tok t = pick(semicolons, random);
				return Optional.of(new Variant(real, kind, "dropped ';'", t.line(), splice(text, t, "")));
			}
			case FIELD_NUMBER_ZERO, FIELD_NUMBER_EDGE -> {
				if (fieldNumbers.isEmpty()) {
					return Optional.empty();
				}
				Tok t = m.tokens.get(pick(fieldNumbers, random));
				String number = kind == Kind.FIELD_NUMBER_ZERO ? "0" : pick(EDGE_NUMBERS, random);
				return Optional.of(new Variant(real, kind, "field number " + t.text() + " -> " + number, t.line(),
						splice(text, t, number)));
			}
			case FIELD_NUMBER_DUPLICATE, FIELD_NAME_DUPLICATE -> {
				if (fieldNumbers.isEmpty()) {
					return Optional.empty();
				}
				int i = pick(fieldNumbers, random);
				int offset = kind == Kind.FIELD_NUMBER_DUPLICATE ? 0 : -2; // the number, or the name two tokens before
				Tok t = m.tokens.get(i + offset);
				List<Tok> others = fieldNumbers.stream().map(j -> m.tokens.get(j + offset))
						.filter(o -> o.block() == t.block() && !o.text().equals(t.text())).toList();
				if (others.isEmpty()) {
					return Optional.empty();
				}
				String other = pick(others, random).text();
				return Optional.of(new Variant(real, kind, "'" + t.text() + "' -> '" + other + "'", t.line(),
						splice(text, t, other)));
			}
			case TYPE_UNKNOWN -> {
				if (fieldNumbers.isEmpty()) {
					return Optional.empty();
				}
				Tok type = m.tokens.get(pick(fieldNumbers, random) - 3);
				if (!type.isIdent()) {
					return Optional.empty();
				}
				return Optional.of(new Variant(real, kind, "type " + type.text() + " -> NoSuchType", type.line(),
						splice(text, type, "NoSuchType")));
			}
			case LABEL_CHANGE -> {
				List<Tok> labels = pickable.stream().filter(t -> LABELS.contains(t.text())).toList();
				if (labels.isEmpty()) {
					return Optional.empty();
				}
				Tok t = pick(labels, random);
				String label = pick(LABELS, random);
				// protoc refuses a default on a repeated field; KSE skips option values on purpose (see pickable).
				if (label.equals(t.text()) || label.equals("repeated") && m.hasOptions(t)) {
					return Optional.empty();
				}
				return Optional.of(new Variant(real, kind, "label " + t.text() + " -> '" + label + "'", t.line(),
						splice(text, t, label)));
			}
			case INSERT_TOKEN -> {
				Tok t = pick(pickable, random);
				String inserted = pick(INSERTED, random);
				return Optional.of(new Variant(real, kind, "inserted '" + inserted + "' before '" + t.text() + "'",
						t.line(), text.substring(0, t.start()) + inserted + " " + text.substring(t.start())));
			}
			default -> throw new IllegalArgumentException(kind.toString());
			}
		}

		/**
		 * Option values are not mutated: KSE parses options ({@code [default = 0]},
		 * {@code option x = y;}) but leaves them unused on purpose (see ProtoReader), it neither knows
		 * the option names nor checks a default against its field's type, where protoc does both. A
		 * mutant there would only measure that documented leniency.
		 */
		private static boolean pickable(Tok t) {
			return !t.inOption();
		}

		/** Whether the statement that starts with {@code first} carries options {@code [...]}. */
		private boolean hasOptions(Tok first) {
			for (int i = tokens.indexOf(first); i < tokens.size() && !tokens.get(i).text().equals(";"); i++) {
				if (tokens.get(i).text().equals("[")) {
					return true;
				}
			}
			return false;
		}

		/** Indexes of field-number tokens: {@code type name = N} inside a block. */
		private List<Integer> fieldNumberIndexes() {
			List<Integer> result = new ArrayList<>();
			for (int i = 3; i < tokens.size(); i++) {
				Tok n = tokens.get(i);
				if (n.isInt() && !n.inOption() && n.block() >= 0 && tokens.get(i - 1).text().equals("=")
						&& tokens.get(i - 2).isIdent() && (tokens.get(i - 3).isIdent() || tokens.get(i - 3).text().equals(">"))
						&& !tokens.get(i - 3).text().equals("option")) {
					result.add(i);
				}
			}
			return result;
		}

		private static String splice(String text, Tok t, String replacement) {
			return text.substring(0, t.start()) + replacement + text.substring(t.end());
		}

		private static <T> T pick(List<T> list, Random random) {
			return list.get(random.nextInt(list.size()));
		}

		/** Enough of the proto lexical grammar for the real files: comments, strings, names, numbers, symbols. */
		private void tokenize(String text) {
			int line = 1;
			Deque<Integer> blocks = new ArrayDeque<>();
			int bracketDepth = 0;
			boolean inOptionStatement = false;
			int i = 0;
			while (i < text.length()) {
				char c = text.charAt(i);
				int start = i;
				if (c == '\n') {
					line++;
					i++;
					continue;
				}
				if (Character.isWhitespace(c)) {
					i++;
					continue;
				}
				if (text.startsWith("//", i)) {
					while (i < text.length() && text.charAt(i) != '\n') {
						i++;
					}
					continue;
				}
				if (text.startsWith("/*", i)) {
					int end = text.indexOf("*/", i + 2);
					end = end < 0 ? text.length() : end + 2;
					line += (int) text.substring(i, end).chars().filter(ch -> ch == '\n').count();
					i = end;
					continue;
				}
				if (c == '"' || c == '\'') {
					i++;
					while (i < text.length() && text.charAt(i) != c && text.charAt(i) != '\n') {
						i += text.charAt(i) == '\\' ? 2 : 1;
					}
					i = Math.min(text.length(), i + 1);
				} else if (Character.isLetterOrDigit(c) || c == '_') {
					while (i < text.length() && (Character.isLetterOrDigit(text.charAt(i)) || text.charAt(i) == '_'
							|| (Character.isDigit(c) && text.charAt(i) == '.'))) {
						i++;
					}
				} else {
					i++;
				}
				String s = text.substring(start, i);
				if (s.equals("option") && bracketDepth == 0) {
					inOptionStatement = true;
				}
				if (s.equals("[")) {
					bracketDepth++;
				}
				boolean inOption = inOptionStatement || bracketDepth > 0;
				if (s.equals("]")) {
					bracketDepth = Math.max(0, bracketDepth - 1);
				}
				if (s.equals(";")) {
					inOptionStatement = false;
				}
				if (s.equals("}") && !blocks.isEmpty()) {
					blocks.pop();
				}
				tokens.add(new Tok(s, start, i, line, blocks.isEmpty() ? -1 : blocks.peek(), inOption));
				if (s.equals("{")) {
					blocks.push(tokens.size() - 1);
				}
			}
		}
	}

	// ---- protoc's view: a FileDescriptorSet, read from the protobuf wire format

	/**
	 * Just enough of descriptor.proto: FileDescriptorSet.file = 1; FileDescriptorProto.package = 2,
	 * message_type = 4, enum_type = 5; DescriptorProto.name = 1, field = 2, nested_type = 3,
	 * enum_type = 4, options = 7 (MessageOptions.map_entry = 7); FieldDescriptorProto.name = 1,
	 * number = 3; EnumDescriptorProto.name = 1, value = 2; EnumValueDescriptorProto.name = 1, number = 2.
	 */
	static final class Descriptors {

		private Descriptors() {
		}

		/** Same shape as {@link ProtocAgreementTest#kseTypes}. */
		static Map<String, List<String>> types(byte[] fileDescriptorSet) {
			Map<String, List<String>> types = new TreeMap<>();
			for (Wire file : new Wire(fileDescriptorSet).all(1)) {
				String pkg = file.string(2).orElse("");
				String prefix = pkg.isEmpty() ? "" : pkg + ".";
				for (Wire message : file.all(4)) {
					addMessage(types, prefix, message);
				}
				for (Wire enumType : file.all(5)) {
					addEnum(types, prefix, enumType);
				}
			}
			return types;
		}

		private static void addMessage(Map<String, List<String>> types, String prefix, Wire message) {
			String name = prefix + message.string(1).orElseThrow();
			types.put("message " + name,
					message.all(2).stream().map(f -> f.string(1).orElseThrow() + " = " + f.varint(3)).toList());
			for (Wire nested : message.all(3)) {
				// protoc models map<K, V> as a nested XxxEntry message; KSE as a field: not a type of its own.
				boolean mapEntry = nested.all(7).stream().anyMatch(options -> options.varint(7) != 0);
				if (!mapEntry) {
					addMessage(types, name + ".", nested);
				}
			}
			for (Wire enumType : message.all(4)) {
				addEnum(types, name + ".", enumType);
			}
		}

		private static void addEnum(Map<String, List<String>> types, String prefix, Wire enumType) {
			types.put("enum " + prefix + enumType.string(1).orElseThrow(), enumType.all(2).stream()
					.map(v -> v.string(1).orElseThrow() + " = " + (int) v.varint(2)).toList());
		}
	}

	/** One protobuf message in wire format: its fields by number, in order (varints and length-delimited only). */
	static final class Wire {

		private final Map<Integer, List<Object>> fields = new LinkedHashMap<>();

		Wire(byte[] bytes) {
			int[] pos = { 0 };
			while (pos[0] < bytes.length) {
				long key = varint(bytes, pos);
				int number = (int) (key >>> 3);
				Object value = switch ((int) (key & 7)) {
				case 0 -> varint(bytes, pos);
				case 1 -> skip(bytes, pos, 8);
				case 2 -> {
					int length = (int) varint(bytes, pos);
					byte[] content = new byte[length];
					System.arraycopy(bytes, pos[0], content, 0, length);
					pos[0] += length;
					yield content;
				}
				case 5 -> skip(bytes, pos, 4);
				default -> throw new IllegalArgumentException("wire type " + (key & 7) + " at " + pos[0]);
				};
				fields.computeIfAbsent(number, n -> new ArrayList<>()).add(value);
			}
		}

		/** Every occurrence of a length-delimited field, read as a message. */
		List<Wire> all(int number) {
			return fields.getOrDefault(number, List.of()).stream().map(v -> new Wire((byte[]) v)).toList();
		}

		Optional<String> string(int number) {
			List<Object> values = fields.getOrDefault(number, List.of());
			return values.isEmpty() ? Optional.empty()
					: Optional.of(new String((byte[]) values.get(values.size() - 1), StandardCharsets.UTF_8));
		}

		/** The last value of a varint field, 0 when absent. */
		long varint(int number) {
			List<Object> values = fields.getOrDefault(number, List.of());
			return values.isEmpty() ? 0 : (Long) values.get(values.size() - 1);
		}

		private static long varint(byte[] bytes, int[] pos) {
			long result = 0;
			for (int shift = 0; shift < 64; shift += 7) {
				byte b = bytes[pos[0]++];
				result |= (long) (b & 0x7f) << shift;
				if (b >= 0) {
					return result;
				}
			}
			throw new IllegalArgumentException("varint longer than 10 bytes");
		}

		private static Object skip(byte[] bytes, int[] pos, int length) {
			pos[0] += length;
			return null;
		}
	}
}
