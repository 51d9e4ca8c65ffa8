package org.kse.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.kse.cli.Kse;

/**
 * The README's command list and {@code kse --help} name the same commands, and each command's
 * line in the README the options its {@code --help} lists (issue 18, item 6): a new option
 * that only one of them mentions fails here.
 */
class HelpAndReadmeTest {

	private static final Path REPOSITORY = Path.of(System.getProperty("kse.repository", "../.."));
	private static final Pattern OPTION = Pattern.compile("(?<![\\w-])(--?[a-zA-Z][\\w-]*)");
	private static final Pattern ALIAS = Pattern.compile("(?<![\\w-])(-[a-zA-Z]), (--[a-zA-Z][\\w-]*)");
	/** Each short option's long form, as the commands' help texts pair them ("-o, --output"). */
	private static final Map<String, String> LONG_FORMS = new HashMap<>();

	@Test
	void theReadmeListsEveryCommandAndEveryOptionOfKseHelp() throws IOException {
		Map<String, Set<String>> help = helpCommands();
		Map<String, Set<String>> readme = readmeCommands();
		assertEquals(help.keySet(), readme.keySet(), "commands of kse --help against the README's list");
		for (String command : help.keySet()) {
			assertEquals(help.get(command), readme.get(command), "options of kse " + command + " --help against its README line");
		}
	}

	@Test
	void kseDemoHelpHasTheOptionsTheDemoScriptTakes() throws IOException {
		String script = Files.readString(REPOSITORY.resolve("releng/demo.sh"));
		Set<String> taken = new TreeSet<>();
		Matcher cases = Pattern.compile("^\\s+(--[a-z-]+)\\)", Pattern.MULTILINE).matcher(script);
		while (cases.find()) {
			taken.add(cases.group(1));
		}
		assertTrue(!taken.isEmpty(), "the demo script's options");
		assertEquals(taken, helpCommands().get("demo"));
	}

	/** The README's block after "## The command line": each "kse <command>" line and the lines indented under it. */
	private static Map<String, Set<String>> readmeCommands() throws IOException {
		String text = Files.readString(REPOSITORY.resolve("README.md"), StandardCharsets.UTF_8);
		int section = text.indexOf("## The command line");
		int start = text.indexOf("```\n", section) + 4;
		String block = text.substring(start, text.indexOf("```", start));
		Map<String, Set<String>> commands = new LinkedHashMap<>();
		Set<String> current = null;
		for (String line : block.split("\n")) {
			if (line.startsWith("kse ")) {
				String name = line.split("\\s+")[1];
				if (name.startsWith("<") || name.equals("help")) {
					current = null;
					continue;
				}
				current = commands.computeIfAbsent(name, key -> new TreeSet<>());
			}
			if (current != null) {
				for (String option : options(line.replaceFirst("\\s{2,}[a-z][^\\[]*$", ""))) {
					current.add(LONG_FORMS.getOrDefault(option, option));
				}
			}
		}
		return commands;
	}

	/** The commands of kse --help, each with the long options of its own --help (a short one stands for its long form). */
	private static Map<String, Set<String>> helpCommands() {
		String usage = run("--help");
		Map<String, Set<String>> commands = new LinkedHashMap<>();
		Matcher command = Pattern.compile("^  ([a-z][a-z-]+) ", Pattern.MULTILINE).matcher(usage.substring(usage.indexOf("commands:")));
		while (command.find()) {
			String name = command.group(1);
			if (name.equals("help")) {
				continue;
			}
			String help = run(name, "--help");
			Matcher alias = ALIAS.matcher(help);
			while (alias.find()) {
				LONG_FORMS.put(alias.group(1), alias.group(2));
			}
			Set<String> options = new TreeSet<>();
			for (String option : options(help)) {
				options.add(LONG_FORMS.getOrDefault(option, option));
			}
			options.remove("--help");
			commands.put(name, options);
		}
		return commands;
	}

	private static Set<String> options(String text) {
		Set<String> found = new TreeSet<>();
		Matcher matcher = OPTION.matcher(text);
		while (matcher.find()) {
			found.add(matcher.group(1));
		}
		return found;
	}

	private static String run(String... args) {
		ByteArrayOutputStream out = new ByteArrayOutputStream();
		try (PrintStream stream = new PrintStream(out, true, StandardCharsets.UTF_8)) {
			assertEquals(Kse.OK, new Kse(stream, stream).run(args), () -> String.join(" ", args) + ": " + out);
		}
		return out.toString(StandardCharsets.UTF_8);
	}
}
