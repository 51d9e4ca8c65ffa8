package org.kse.maven;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.apache.maven.plugin.MojoExecutionException;

/**
 * The models a goal works on: each entry of {@code <models>} is a file or a glob, relative to
 * the project's folder ({@code models/**}{@code /*.stct}, {@code behaviours/Goalie.stct}); the
 * {@code <excludes>} globs take files out again. Globs are read as Maven's filesets read them:
 * {@code *} and {@code ?} within a folder name, {@code **} across folders, also none
 * ({@code models/**}{@code /*.stct} matches {@code models/Goalie.stct}). The result is sorted, so that the generator
 * sees the models, and the stamp records them, in the same order on every machine.
 */
final class ModelSelection {

	private ModelSelection() {
	}

	static List<Path> select(Path basedir, List<String> includes, List<String> excludes) throws MojoExecutionException {
		TreeSet<Path> selected = new TreeSet<>();
		for (String include : includes) {
			String pattern = include.trim().replace('\\', '/').replaceFirst("^(\\./)+", "");
			if (pattern.isEmpty()) {
				continue;
			}
			if (!isGlob(pattern)) {
				Path file = basedir.resolve(pattern).normalize();
				// a model named by its path is meant to exist: a typo must not pass as "no models"
				if (!Files.isRegularFile(file)) {
					throw new MojoExecutionException("KSE: the model " + file + " (from <models>) does not exist or is not a file");
				}
				selected.add(file);
				continue;
			}
			Path root = basedir.resolve(fixedPrefix(pattern)).normalize();
			if (!Files.isDirectory(root)) {
				continue;
			}
			// an absolute glob is matched from the root of the file system, a relative one from the project
			boolean absolute = Path.of(fixedPrefix(pattern)).isAbsolute();
			Path from = absolute ? root.getRoot() : basedir;
			Pattern matcher = glob(absolute ? pattern.substring(pattern.indexOf('/') + 1) : pattern);
			try (Stream<Path> walk = Files.walk(root)) {
				walk.filter(Files::isRegularFile).map(Path::normalize).filter(file -> matches(matcher, from, file)).forEach(selected::add);
			} catch (IOException e) {
				throw new MojoExecutionException("KSE: cannot list the models under " + root + ": " + e.getMessage(), e);
			}
		}
		List<Pattern> excluded = new ArrayList<>();
		for (String exclude : excludes) {
			String pattern = exclude.trim().replace('\\', '/').replaceFirst("^(\\./)+", "");
			if (!pattern.isEmpty()) {
				excluded.add(glob(pattern));
			}
		}
		return selected.stream().filter(file -> excluded.stream().noneMatch(matcher -> matches(matcher, basedir, file))).toList();
	}

	/** Matched against the path relative to the project, so that its folder's name needs no escaping. */
	private static boolean matches(Pattern glob, Path from, Path file) {
		Path relative = from.normalize().relativize(file);
		return glob.matcher(relative.toString().replace('\\', '/')).matches();
	}

	static Pattern glob(String pattern) {
		StringBuilder regex = new StringBuilder();
		for (int i = 0; i < pattern.length(); i++) {
			char c = pattern.charAt(i);
			if (pattern.startsWith("**/", i)) {
				regex.append("(?:.*/)?");
				i += 2;
			} else if (pattern.startsWith("**", i)) {
				regex.append(".*");
				i += 1;
			} else if (c == '*') {
				regex.append("[^/]*");
			} else if (c == '?') {
				regex.append("[^/]");
			} else {
				regex.append(Pattern.quote(String.valueOf(c)));
			}
		}
		return Pattern.compile(regex.toString());
	}

	private static boolean isGlob(String pattern) {
		return pattern.indexOf('*') >= 0 || pattern.indexOf('?') >= 0;
	}

	/** The folders of a glob before its first wildcard: where the walk starts. */
	private static String fixedPrefix(String pattern) {
		String[] parts = pattern.split("/");
		StringBuilder prefix = new StringBuilder();
		for (String part : parts) {
			if (isGlob(part)) {
				break;
			}
			prefix.append(part).append('/');
		}
		return prefix.isEmpty() ? "." : prefix.toString();
	}
}
