package org.kse.ui.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.net.ConnectException;
import java.net.HttpURLConnection;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.net.Socket;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.help.HelpSystem;
import org.eclipse.help.IToc;
import org.eclipse.help.ITopic;
import org.eclipse.help.internal.server.WebappManager;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.handlers.IHandlerService;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.kse.testing.ui.Ui;
import org.kse.testing.ui.UnexpectedDialogs;

/**
 * The KSE user manual as Eclipse help: its book in the help contents, every topic and every link
 * of it there, the examples it prints equal to the example files, and the help window opened
 * from Help > Help Contents, served on loopback only.
 */
@ExtendWith(UnexpectedDialogs.class)
class HelpTest {

	private static final String BOOK = "KSE User Manual";
	private static final Pattern LINK = Pattern.compile("href=\"([^\"#:]*)(#[^\"]*)?\"");

	private static IToc book() {
		return Arrays.stream(HelpSystem.getTocs()).filter(toc -> BOOK.equals(toc.getLabel())).findFirst()
				.orElseThrow(() -> new AssertionError("no book '" + BOOK + "' in the help contents: "
						+ Arrays.stream(HelpSystem.getTocs()).map(IToc::getLabel).toList()));
	}

	private static void collect(ITopic[] topics, List<ITopic> into) {
		for (ITopic topic : topics) {
			into.add(topic);
			collect(topic.getSubtopics(), into);
		}
	}

	private static String page(String href) {
		try (InputStream in = HelpSystem.getHelpContent(href.replaceFirst("#.*", ""))) {
			assertNotNull(in, () -> "the help has no page " + href);
			return new String(in.readAllBytes(), StandardCharsets.UTF_8);
		} catch (IOException e) {
			throw new AssertionError("cannot read " + href, e);
		}
	}

	@Test
	void theManualIsABookOfTheHelpWithTheStepsRulesGrammarAndExamples() {
		List<ITopic> topics = new ArrayList<>();
		collect(book().getTopics(), topics);
		List<String> labels = topics.stream().map(ITopic::getLabel).toList();
		for (String expected : List.of("From formula to robot, step by step", "Liveness formulas", "Statechart rules", "Transition expressions",
				"Generated code", "Examples", "2. Write the liveness formula", "Validation rules")) {
			assertTrue(labels.contains(expected), () -> expected + " in " + labels);
		}
		for (ITopic topic : topics) {
			String text = page(topic.getHref());
			assertTrue(text.contains("<h1>"), () -> topic.getHref() + " is a page with a title");
			String anchor = topic.getHref().contains("#") ? topic.getHref().substring(topic.getHref().indexOf('#') + 1) : null;
			assertTrue(anchor == null || text.contains("id=\"" + anchor + "\""), () -> topic.getHref() + ": the section exists");
		}
		String grammar = page("/org.kse.doc/html/expressions.html");
		assertTrue(grammar.contains("TimeoutAction") && grammar.contains("publish_all"), "the transition grammar");
		String rules = page("/org.kse.doc/html/statecharts.html");
		assertTrue(rules.contains("every OR state has exactly one START child"), "the validation rules");
	}

	@Test
	void everyLinkBetweenThePagesLeadsToAPageAndSection() {
		List<ITopic> topics = new ArrayList<>();
		collect(book().getTopics(), topics);
		Set<String> pages = new LinkedHashSet<>();
		topics.forEach(topic -> pages.add(topic.getHref().replaceFirst("#.*", "")));
		List<String> broken = new ArrayList<>();
		for (String href : pages) {
			String folder = href.substring(0, href.lastIndexOf('/') + 1);
			Matcher link = LINK.matcher(page(href));
			while (link.find()) {
				String target = link.group(1).isEmpty() ? href : folder + link.group(1);
				String anchor = link.group(2);
				try (InputStream in = HelpSystem.getHelpContent(target)) {
					if (in == null) {
						broken.add(href + " -> " + link.group(0));
					} else if (anchor != null && !new String(in.readAllBytes(), StandardCharsets.UTF_8).contains("id=\"" + anchor.substring(1) + "\"")) {
						broken.add(href + " -> " + link.group(0) + " (no such section)");
					}
				} catch (IOException e) {
					broken.add(href + " -> " + link.group(0) + ": " + e.getMessage());
				}
			}
		}
		assertEquals(List.of(), broken, "broken links in the manual");
	}

	@Test
	void theExamplesInTheManualAreTheExampleFormulas() throws IOException {
		String examples = page("/org.kse.doc/html/examples.html");
		Matcher shown = Pattern.compile("<pre class=\"formula\" data-example=\"(\\w+)\">([^<]*)</pre>").matcher(examples);
		int count = 0;
		while (shown.find()) {
			Path file = Path.of(System.getProperty("kse.examples"), shown.group(1), shown.group(1) + ".liveness");
			assertEquals(Files.readString(file).strip(), shown.group(2).strip(), () -> "the manual shows " + file + " as it is");
			count++;
		}
		assertEquals(3, count, "Goalie, Attacker and Defender");
	}

	@Test
	void helpContentsOpensTheManualServedOnLoopbackOnly() throws Exception {
		Set<Shell> before = new LinkedHashSet<>(Arrays.asList(Ui.display().getShells()));
		PlatformUI.getWorkbench().getService(IHandlerService.class).executeCommand("org.eclipse.ui.help.helpContents", null);
		assertTrue(Ui.waitUntil(() -> WebappManager.getPort() > 0, 60_000), "the help server started");
		int port = WebappManager.getPort();
		assertEquals("127.0.0.1", WebappManager.getHost(), "the help server listens on loopback");

		String topic = fetch(port, "/help/topic/org.kse.doc/html/tutorial.html");
		assertTrue(topic.contains("From formula to robot, step by step"), "the tutorial is served");
		String contents = fetch(port, "/help/index.jsp");
		assertTrue(contents.contains("<html") || contents.contains("<HTML"), "the help's pages (JSP) are served");
		String toc = fetch(port, "/help/advanced/tocfragment");
		assertTrue(toc.contains(BOOK), () -> "the book is in the table of contents: " + toc.substring(0, Math.min(400, toc.length())));
		for (InetAddress address : outsideAddresses()) {
			try (Socket socket = new Socket()) {
				socket.connect(new InetSocketAddress(address, port), 1000);
				throw new AssertionError("the help server answers on " + address);
			} catch (ConnectException | java.net.SocketTimeoutException expected) {
				// only loopback
			}
		}

		assertTrue(Ui.waitUntil(() -> Arrays.stream(Ui.display().getShells()).anyMatch(shell -> !before.contains(shell) && shell.isVisible()), 30_000),
				"a help window opens");
		Shell window = Arrays.stream(Ui.display().getShells()).filter(shell -> !before.contains(shell) && shell.isVisible()).findFirst().orElseThrow();
		window.setSize(1100, 760);
		Ui.settle(4000);
		assertEquals("/org.kse.doc/html/overview.html",
				org.eclipse.core.runtime.Platform.getPreferencesService().getString("org.eclipse.help.base", "help_home", "", null),
				"the help starts at the KSE overview");
		Ui.screenshotOf(window, "30-help-contents");
		window.close();
		Ui.settle(500);
		PlatformUI.getWorkbench().getHelpSystem().displayHelpResource("/org.kse.doc/html/tutorial.html");
		Ui.settle(4000);
		Shell tutorial = Arrays.stream(Ui.display().getShells()).filter(shell -> !before.contains(shell) && shell.isVisible()).findFirst()
				.orElseThrow(() -> new AssertionError("the help window shows a topic"));
		tutorial.setSize(1100, 760);
		Ui.settle(1000);
		Ui.screenshotOf(tutorial, "31-help-tutorial");
		tutorial.close();
	}

	private static String fetch(int port, String path) throws IOException {
		HttpURLConnection connection = (HttpURLConnection) URI.create("http://127.0.0.1:" + port + path).toURL().openConnection();
		connection.setConnectTimeout(5000);
		connection.setReadTimeout(30_000);
		assertEquals(200, connection.getResponseCode(), () -> path);
		try (InputStream in = connection.getInputStream()) {
			return new String(in.readAllBytes(), StandardCharsets.UTF_8);
		}
	}

	private static List<InetAddress> outsideAddresses() throws IOException {
		List<InetAddress> addresses = new ArrayList<>();
		for (NetworkInterface network : Collections.list(NetworkInterface.getNetworkInterfaces())) {
			if (network.isUp() && !network.isLoopback()) {
				network.inetAddresses().filter(address -> address instanceof java.net.Inet4Address).forEach(addresses::add);
			}
		}
		return addresses;
	}
}
