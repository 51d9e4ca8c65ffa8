import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;
import java.util.zip.ZipOutputStream;

/**
 * Makes the kse command's plain-class-path launcher (ADR 0023) from the headless product:
 * its jars without their signature files (the JVM's ahead-of-time cache skips classes of signed
 * jars), the class path in a fixed order, the start script, and the cache itself from a
 * training run of every headless command.
 * <p>
 * Run by the build as a single-file program:
 * java MakeLauncher.java PLUGINS OUT SCRIPT FORMULA MODEL [FILE...], each FILE copied into lib/.
 */
public final class MakeLauncher {

	private static final Pattern SIGNATURE = Pattern.compile("META-INF/[^/]+\\.(SF|RSA|DSA|EC)", Pattern.CASE_INSENSITIVE);

	/** The JVM options of the start script; the training run must use the same ones for the cache to apply. */
	static final List<String> JVM_OPTIONS = List.of("-Xss16m", "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1",
			"--sun-misc-unsafe-memory-access=allow", "-Djava.awt.headless=true",
			// Guice would generate classes at run time, which no cache can hold; reflection starts sooner
			"-Dguice_bytecode_gen_option=DISABLED");

	public static void main(String[] args) throws Exception {
		if (args.length < 5) {
			throw new IllegalArgumentException("usage: MakeLauncher <product-plugins> <out> <start-script> <formula> <model> [file...]");
		}
		Path plugins = Path.of(args[0]);
		Path out = Path.of(args[1]);
		Path script = Path.of(args[2]);
		deleteTree(out);
		Path lib = Files.createDirectories(out.resolve("lib"));
		List<String> classPath = new ArrayList<>();
		try (Stream<Path> entries = Files.list(plugins)) {
			for (Path entry : entries.sorted(Comparator.comparing(Path::toString)).toList()) {
				if (Files.isDirectory(entry)) {
					throw new IOException(entry + ": a bundle unpacked as a folder cannot be cached; give it a jar shape in the product");
				}
				if (entry.toString().endsWith(".jar")) {
					copyUnsigned(entry, lib.resolve(entry.getFileName()));
					classPath.add(entry.getFileName().toString());
				}
			}
		}
		Files.write(out.resolve("lib/classpath"), classPath, StandardCharsets.UTF_8);
		Path bin = Files.createDirectories(out.resolve("bin"));
		Files.copy(script, bin.resolve("kse"), StandardCopyOption.REPLACE_EXISTING);
		Files.setPosixFilePermissions(bin.resolve("kse"), PosixFilePermissions.fromString("rwxr-xr-x"));
		Files.write(out.resolve("lib/jvm-options"), JVM_OPTIONS, StandardCharsets.UTF_8);
		for (int i = 5; i < args.length; i++) {
			Path file = Path.of(args[i]);
			Files.copy(file, lib.resolve(file.getFileName()), StandardCopyOption.REPLACE_EXISTING);
		}
		train(out, lib, classPath, Path.of(args[3]), Path.of(args[4]));
		System.out.println("kse launcher: " + classPath.size() + " jars, cache " + Files.size(out.resolve("lib/kse.aot")) / (1024 * 1024) + " MB, in " + out);
	}

	/** A jar with the same entries minus the signature files; nothing else changes. */
	private static void copyUnsigned(Path from, Path to) throws IOException {
		try (ZipInputStream in = new ZipInputStream(Files.newInputStream(from));
				ZipOutputStream zip = new ZipOutputStream(Files.newOutputStream(to))) {
			for (ZipEntry entry; (entry = in.getNextEntry()) != null;) {
				if (SIGNATURE.matcher(entry.getName()).matches()) {
					continue;
				}
				ZipEntry copy = new ZipEntry(entry.getName());
				if (entry.getLastModifiedTime() != null) {
					copy.setLastModifiedTime(entry.getLastModifiedTime());
				}
				zip.putNextEntry(copy);
				in.transferTo(zip);
				zip.closeEntry();
			}
		}
	}

	/**
	 * Records the cache in a JVM that runs every command once, with the start script's options.
	 * The cache only fits the JDK that made it: the JDK's runtime version is written beside it,
	 * and the start script uses the cache only under that JDK.
	 */
	private static void train(Path out, Path lib, List<String> classPath, Path formula, Path model) throws IOException, InterruptedException {
		Path java = Path.of(System.getProperty("java.home"), "bin", "java");
		Path scratch = Files.createDirectories(out.resolve("training"));
		List<String> command = new ArrayList<>(List.of(java.toString()));
		command.addAll(JVM_OPTIONS);
		command.add("-XX:AOTCacheOutput=" + lib.resolve("kse.aot"));
		command.add("-cp");
		command.add(String.join(":", classPath.stream().map(jar -> lib.resolve(jar).toString()).toList()));
		command.addAll(List.of("org.kse.cli.StartupTraining", scratch.toString(), formula.toString(), model.toString()));
		Process training = new ProcessBuilder(command).redirectErrorStream(true).start();
		String log;
		try (InputStream output = training.getInputStream()) {
			log = new String(output.readAllBytes(), StandardCharsets.UTF_8);
		}
		if (training.waitFor() != 0 || !Files.exists(lib.resolve("kse.aot"))) {
			throw new IOException("the training run of the kse launcher's cache failed:\n" + log);
		}
		Files.writeString(lib.resolve("kse.aot.jdk"), runtimeVersion(Path.of(System.getProperty("java.home"))) + "\n", StandardCharsets.UTF_8);
		deleteTree(scratch);
	}

	/** The JAVA_RUNTIME_VERSION line of a JDK's release file: what the start script compares. */
	static String runtimeVersion(Path javaHome) throws IOException {
		for (String line : Files.readAllLines(javaHome.resolve("release"), StandardCharsets.UTF_8)) {
			if (line.startsWith("JAVA_RUNTIME_VERSION=")) {
				return line;
			}
		}
		throw new IOException(javaHome.resolve("release") + ": no JAVA_RUNTIME_VERSION");
	}

	private static void deleteTree(Path root) throws IOException {
		if (!Files.exists(root)) {
			return;
		}
		try (Stream<Path> paths = Files.walk(root)) {
			for (Path path : paths.sorted(Comparator.reverseOrder()).toList()) {
				Files.delete(path);
			}
		}
	}
}
