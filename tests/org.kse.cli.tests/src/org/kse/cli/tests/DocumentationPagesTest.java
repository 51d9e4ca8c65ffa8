package org.kse.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * The newcomer's pages (issue 18, item 5) exist twice, as Markdown in docs/ for the repository
 * and as pages of the Eclipse help: both are listed, both say the same (the same sections, the
 * same commands and code), every relative link of the docs and the README leads to a file and a
 * section that exist, and the complete activity of "Writing activities" is the one
 * tests/cmake-package/run.sh builds and plays. A page renamed, a section added to one twin only,
 * a command edited in one place, or example code that no longer compiles fails here or there.
 */
class DocumentationPagesTest {

	private static final Path REPOSITORY = Path.of(System.getProperty("kse.repository", "../.."));
	private static final Path DOCS = REPOSITORY.resolve("docs");
	private static final Path HELP = REPOSITORY.resolve("bundles/org.kse.doc/html");
	/** The pages a newcomer reads, in the order of the path through them. */
	private static final List<String> NEWCOMER_PAGES = List.of("concepts", "getting-started", "writing-activities", "how-tos", "troubleshooting");
	private static final Path EXAMPLE = REPOSITORY.resolve("tests/cmake-package/chaser");

	private static final Pattern TOC_PAGE = Pattern.compile("href=\"html/([\\w-]+)\\.html[\"#]");
	private static final Pattern MD_LINK = Pattern.compile("\\]\\(([^)\\s]+)\\)");
	private static final Pattern MD_HEADING = Pattern.compile("^(#{1,6}) (.+)$", Pattern.MULTILINE);
	private static final Pattern MD_CODE = Pattern.compile("^( *)```[\\w-]*\\n(.*?)\\n\\1```$", Pattern.MULTILINE | Pattern.DOTALL);
	private static final Pattern HTML_LINK = Pattern.compile("href=\"([^\"]*)\"");
	private static final Pattern HTML_HEADING = Pattern.compile("<h([1-6])[^>]*>(.*?)</h\\1>", Pattern.DOTALL);
	private static final Pattern HTML_PRE = Pattern.compile("<pre[^>]*>(.*?)</pre>", Pattern.DOTALL);
	private static final Pattern HTML_ID = Pattern.compile("id=\"([^\"]+)\"");
	private static final Pattern MD_PICTURE = Pattern.compile("!\\[[^\\]]*\\]\\(([^)\\s]+)\\)");
	private static final Pattern HTML_PICTURE = Pattern.compile("<img[^>]*\\ssrc=\"([^\"]+)\"");

	@Test
	void everyNewcomerPageIsInDocsAndInTheHelpsTableOfContents() throws IOException {
		Set<String> toc = tocPages();
		for (String page : NEWCOMER_PAGES) {
			assertTrue(Files.isRegularFile(DOCS.resolve(page + ".md")), () -> "docs/" + page + ".md exists");
			assertTrue(Files.isRegularFile(HELP.resolve(page + ".html")), () -> "the help page " + page + ".html exists");
			assertTrue(toc.contains(page), () -> page + ".html is in toc.xml: " + toc);
		}
	}

	@Test
	void everyPageOfTheHelpIsInTheTableOfContentsAndEveryTwinHasBothForms() throws IOException {
		Set<String> toc = tocPages();
		try (Stream<Path> files = Files.list(HELP)) {
			for (Path file : files.filter(f -> f.toString().endsWith(".html")).toList()) {
				String name = file.getFileName().toString().replaceFirst("\\.html$", "");
				assertTrue(toc.contains(name), () -> file + " is a page nobody can reach: add it to toc.xml");
			}
		}
		for (String page : toc) {
			assertTrue(Files.isRegularFile(HELP.resolve(page + ".html")), () -> "toc.xml lists " + page + ".html, which does not exist");
		}
		assertFalse(twins().isEmpty(), "pages written both as docs/*.md and as help pages");
	}

	@Test
	void bothFormsOfAPageShowTheSamePicturesAndEachPictureIsTheSameFileInBoth() throws IOException {
		for (String page : twins()) {
			List<String> inMarkdown = all(MD_PICTURE, read(DOCS.resolve(page + ".md")));
			List<String> inHelp = all(HTML_PICTURE, read(HELP.resolve(page + ".html")));
			assertEquals(inMarkdown, inHelp, () -> page + ": the pictures of docs/" + page + ".md and of " + page + ".html, in order");
			for (String picture : inMarkdown) {
				Path docs = DOCS.resolve(picture).normalize();
				Path help = HELP.resolve(picture).normalize();
				assertTrue(docs.startsWith(DOCS) && Files.isRegularFile(docs), () -> page + ": docs/" + picture + " exists");
				assertTrue(help.startsWith(HELP) && Files.isRegularFile(help), () -> page + ": the help's " + picture + " exists");
				assertTrue(java.util.Arrays.equals(Files.readAllBytes(docs), Files.readAllBytes(help)),
						() -> page + ": docs/" + picture + " and the help's copy are the same picture");
			}
		}
	}

	private static List<String> all(Pattern pattern, String text) {
		List<String> found = new ArrayList<>();
		Matcher matcher = pattern.matcher(text);
		while (matcher.find()) {
			found.add(matcher.group(1));
		}
		return found;
	}

	@Test
	void bothFormsOfAPageHaveTheSameSectionsAndTheSameCode() throws IOException {
		for (String page : twins()) {
			String markdown = read(DOCS.resolve(page + ".md"));
			String help = read(HELP.resolve(page + ".html"));
			assertEquals(markdownHeadings(markdown), htmlHeadings(help), () -> page + ": the sections of docs/" + page + ".md and of " + page + ".html");
			List<String> pres = new ArrayList<>();
			Matcher pre = HTML_PRE.matcher(help);
			while (pre.find()) {
				pres.add(unescape(pre.group(1)));
			}
			List<String> blocks = markdownCode(markdown);
			assertEquals(blocks, pres, () -> page + ": the commands and code of docs/" + page + ".md and of " + page + ".html, in order");
		}
	}

	@Test
	void everyRelativeLinkOfTheDocsAndTheReadmeLeadsToAFileAndASection() throws IOException {
		List<String> broken = new ArrayList<>();
		List<Path> markdown = new ArrayList<>();
		markdown.add(REPOSITORY.resolve("README.md"));
		try (Stream<Path> files = Files.list(DOCS)) {
			files.filter(f -> f.toString().endsWith(".md")).sorted().forEach(markdown::add);
		}
		for (Path file : markdown) {
			String text = withoutCode(read(file));
			Matcher link = MD_LINK.matcher(text);
			while (link.find()) {
				String target = link.group(1);
				if (target.matches("[a-z]+:.*")) {
					continue; // https:, mailto:: not ours to check offline
				}
				String path = target.replaceFirst("#.*", "");
				String anchor = target.contains("#") ? target.substring(target.indexOf('#') + 1) : null;
				Path resolved = path.isEmpty() ? file : file.getParent().resolve(path).normalize();
				String where = REPOSITORY.relativize(file) + ":" + line(text, link.start()) + ": (" + target + ")";
				if (!Files.exists(resolved)) {
					broken.add(where + " leads to no file");
				} else if (anchor != null && resolved.toString().endsWith(".md") && !markdownAnchors(read(resolved)).contains(anchor)) {
					broken.add(where + ": " + REPOSITORY.relativize(resolved) + " has no section #" + anchor);
				} else if (anchor != null && resolved.toString().endsWith(".html") && !htmlIds(read(resolved)).contains(anchor)) {
					broken.add(where + ": " + REPOSITORY.relativize(resolved) + " has no id " + anchor);
				}
			}
		}
		for (String page : tocPages()) {
			Path file = HELP.resolve(page + ".html");
			if (!Files.isRegularFile(file)) {
				continue; // said by the test of the table of contents
			}
			String text = read(file);
			Matcher link = HTML_LINK.matcher(text);
			while (link.find()) {
				String target = unescape(link.group(1));
				if (target.matches("[a-z]+:.*")) {
					continue;
				}
				String path = target.replaceFirst("#.*", "");
				String anchor = target.contains("#") ? target.substring(target.indexOf('#') + 1) : null;
				Path resolved = path.isEmpty() ? file : file.getParent().resolve(path).normalize();
				String where = REPOSITORY.relativize(file) + ":" + line(text, link.start()) + ": href=\"" + target + "\"";
				if (!resolved.startsWith(HELP.normalize())) {
					broken.add(where + " leaves the help bundle (the help can serve only its own files)");
				} else if (!Files.exists(resolved)) {
					broken.add(where + " leads to no file");
				} else if (anchor != null && !htmlIds(read(resolved)).contains(anchor)) {
					broken.add(where + ": " + resolved.getFileName() + " has no id " + anchor);
				}
			}
		}
		assertEquals(List.of(), broken, "broken links");
	}

	@Test
	void theCompleteActivityOfWritingActivitiesIsTheOneTheCmakePackageTestBuildsAndPlays() throws IOException {
		List<String> markdown = markdownCode(read(DOCS.resolve("writing-activities.md")));
		List<String> help = new ArrayList<>();
		Matcher pre = HTML_PRE.matcher(read(HELP.resolve("writing-activities.html")));
		while (pre.find()) {
			help.add(unescape(pre.group(1)));
		}
		Path activity = EXAMPLE.resolve("activities/ChaseBall");
		for (Path file : List.of(activity.resolve("ChaseBall.h"), activity.resolve("ChaseBall.cpp"), activity.resolve("CMakeLists.txt"),
				EXAMPLE.resolve("CMakeLists.txt"))) {
			// the project's own CMakeLists.txt starts with a comment for readers of the repository, which the page leaves out
			String code = read(file).strip();
			if (file.getFileName().toString().equals("CMakeLists.txt")) {
				code = code.replaceFirst("\\A(#[^\\n]*\\n)+", "").strip();
			}
			String printed = code;
			assertTrue(markdown.contains(printed), () -> "docs/writing-activities.md prints " + REPOSITORY.relativize(file) + " as it is");
			assertTrue(help.contains(printed), () -> "writing-activities.html prints " + REPOSITORY.relativize(file) + " as it is");
		}
		// the commands that make the model and play it, run by the script line for line (in the project's folder, kse a function)
		Set<String> script = new LinkedHashSet<>(read(REPOSITORY.resolve("tests/cmake-package/run.sh")).lines().map(String::strip).toList());
		List<String> commands = new ArrayList<>();
		markdown.stream().filter(block -> block.contains("kse transform models/chaser.liveness")).flatMap(String::lines).forEach(commands::add);
		markdown.stream().flatMap(String::lines).filter(line -> line.startsWith("./build/chaser-match")).forEach(commands::add);
		assertEquals(7, commands.size(), () -> "the page's commands from the formula to the match: " + commands);
		for (String command : commands) {
			assertTrue(script.contains(command), () -> "tests/cmake-package/run.sh runs the page's command as it is: " + command);
		}
	}

	/** Pages with both forms: a help page of the table of contents with a docs/*.md of the same name. */
	private static List<String> twins() throws IOException {
		return tocPages().stream().filter(page -> Files.isRegularFile(DOCS.resolve(page + ".md"))).toList();
	}

	private static Set<String> tocPages() throws IOException {
		Set<String> pages = new LinkedHashSet<>();
		Matcher page = TOC_PAGE.matcher(read(REPOSITORY.resolve("bundles/org.kse.doc/toc.xml")));
		while (page.find()) {
			pages.add(page.group(1));
		}
		return pages;
	}

	private static List<String> markdownHeadings(String markdown) {
		List<String> headings = new ArrayList<>();
		Matcher heading = MD_HEADING.matcher(withoutCode(markdown));
		while (heading.find()) {
			headings.add(heading.group(1).length() + " " + heading.group(2).replace("`", "").replaceAll("\\[([^\\]]*)\\]\\([^)]*\\)", "$1").strip());
		}
		return headings;
	}

	private static List<String> htmlHeadings(String html) {
		List<String> headings = new ArrayList<>();
		Matcher heading = HTML_HEADING.matcher(html);
		while (heading.find()) {
			headings.add(heading.group(1) + " " + unescape(heading.group(2).replaceAll("<[^>]+>", "")).strip());
		}
		return headings;
	}

	private static List<String> markdownCode(String markdown) {
		List<String> blocks = new ArrayList<>();
		Matcher code = MD_CODE.matcher(markdown);
		while (code.find()) {
			String indent = code.group(1);
			blocks.add(code.group(2).replaceAll("(?m)^" + indent, "").strip());
		}
		return blocks;
	}

	/** The anchors GitHub gives a page's headings: lower case, punctuation dropped, spaces as '-'. */
	private static Set<String> markdownAnchors(String markdown) {
		Set<String> anchors = new LinkedHashSet<>();
		Matcher heading = MD_HEADING.matcher(withoutCode(markdown));
		while (heading.find()) {
			String text = heading.group(2).replaceAll("\\[([^\\]]*)\\]\\([^)]*\\)", "$1").toLowerCase(Locale.ROOT);
			anchors.add(text.replaceAll("[^\\p{L}\\p{N} _-]", "").replace(' ', '-'));
		}
		return anchors;
	}

	private static Set<String> htmlIds(String html) {
		Set<String> ids = new LinkedHashSet<>();
		Matcher id = HTML_ID.matcher(html);
		while (id.find()) {
			ids.add(id.group(1));
		}
		return ids;
	}

	/** The text with fenced code blanked out (kept as empty lines, so that line numbers stay right). */
	private static String withoutCode(String markdown) {
		Matcher code = MD_CODE.matcher(markdown);
		StringBuilder out = new StringBuilder();
		while (code.find()) {
			code.appendReplacement(out, Matcher.quoteReplacement(code.group().replaceAll("[^\\n]", "")));
		}
		code.appendTail(out);
		return out.toString();
	}

	private static int line(String text, int offset) {
		int line = 1;
		for (int i = 0; i < offset; i++) {
			if (text.charAt(i) == '\n') {
				line++;
			}
		}
		return line;
	}

	private static String unescape(String html) {
		return html.replace("&lt;", "<").replace("&gt;", ">").replace("&quot;", "\"").replace("&#39;", "'").replace("&amp;", "&").strip();
	}

	private static String read(Path file) throws IOException {
		return Files.readString(file, StandardCharsets.UTF_8);
	}
}
