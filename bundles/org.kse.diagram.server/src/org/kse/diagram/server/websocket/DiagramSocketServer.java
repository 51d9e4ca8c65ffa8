package org.kse.diagram.server.websocket;

import java.net.URI;
import java.net.URL;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.util.Base64;
import java.util.function.Supplier;
import java.util.regex.Pattern;

import org.eclipse.jetty.ee10.servlet.ServletContextHandler;
import org.eclipse.jetty.ee10.servlet.ServletHolder;
import org.eclipse.jetty.ee10.websocket.jakarta.server.config.JakartaWebSocketServletContainerInitializer;
import org.eclipse.jetty.server.Handler;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.server.Server;
import org.eclipse.jetty.server.ServerConnector;
import org.eclipse.jetty.util.Callback;
import org.kse.diagram.server.FileSources;
import org.kse.diagram.server.Reasons;
import org.kse.diagram.server.ServedFolder;
import org.kse.diagram.server.StatechartSources;
import org.kse.diagram.server.StatechartServerModule;

import com.google.inject.Guice;
import com.google.inject.Injector;

import jakarta.websocket.server.ServerEndpointConfig;

/**
 * The diagram server on a WebSocket: listens on 127.0.0.1 only, serves the statecharts of one
 * folder, and accepts only connections that present this server's random session token.
 */
public final class DiagramSocketServer implements AutoCloseable {

	public static final String PATH = "/kse";

	private final Server jetty;
	private final String token;

	private final ServedFolder served;

	private DiagramSocketServer(Server jetty, String token, ServedFolder served) {
		this.jetty = jetty;
		this.token = token;
		this.served = served;
	}

	/** Starts serving {@code folder} on a loopback port ({@code 0}: any free one), without the client's page. */
	public static DiagramSocketServer start(Path folder, int port) throws Exception {
		return start(folder, port, null);
	}

	/**
	 * Starts serving {@code folder} on a loopback port ({@code 0}: any free one), and the diagram
	 * client's page from {@code pages} (a folder URL ending in {@code /}) when it is not null.
	 */
	public static DiagramSocketServer start(Path folder, int port, URL pages) throws Exception {
		return start(folder, port, pages, new FileSources());
	}

	/**
	 * Starts serving {@code folder} as {@code sources} hands its statecharts out (a workbench: its
	 * editors' models), on a loopback port, with the client's page from {@code pages} when not null.
	 */
	public static DiagramSocketServer start(Path folder, int port, URL pages, StatechartSources sources) throws Exception {
		byte[] random = new byte[32];
		new SecureRandom().nextBytes(random);
		String token = Base64.getUrlEncoder().withoutPadding().encodeToString(random);
		// GLSP binds its server as a singleton that serves one client application: every
		// connection (a second tab, a second window) gets an injector of its own
		Supplier<Injector> injectors = () -> Guice.createInjector(new StatechartServerModule(folder, sources));
		Server jetty = new Server();
		ServerConnector connector = new ServerConnector(jetty);
		connector.setHost("127.0.0.1");
		connector.setPort(port);
		jetty.addConnector(connector);
		ServletContextHandler context = new ServletContextHandler();
		context.setContextPath("/");
		jetty.setHandler(new LoopbackGuard(context));
		ServedFolder served = new ServedFolder(folder);
		context.addServlet(new ServletHolder(new ModelListServlet(served, token)), "/models");
		// the running matches the live monitor may watch (without their keys)
		context.addServlet(new ServletHolder(new MatchListServlet(token)), MatchListServlet.PATH);
		// the match logs of the folder, read-only, for the page's replay
		context.addServlet(new ServletHolder(new MatchLogServlet(served, token)), MatchLogServlet.PATH + "/*");
		if (pages != null) {
			context.addServlet(new ServletHolder(new PageServlet(pages)), "/*");
		}
		JakartaWebSocketServletContainerInitializer.configure(context, (servletContext, container) -> {
			container.addEndpoint(ServerEndpointConfig.Builder.create(DiagramEndpoint.class, PATH)
					.configurator(new EndpointConfigurator(() -> new DiagramEndpoint(injectors, token), DiagramSocketServer::isLocalOrigin)).build());
			// the live monitor's relay to a kse-match on this machine (the port is known once Jetty listens)
			container.addEndpoint(ServerEndpointConfig.Builder.create(MonitorEndpoint.class, MonitorEndpoint.PATH)
					.configurator(new EndpointConfigurator(() -> new MonitorEndpoint(token), MonitorEndpoint.ownPages(connector::getLocalPort))).build());
		});
		jetty.start();
		return new DiagramSocketServer(jetty, token, served);
	}

	/** The pages {@code /kse} accepts: browsers send the page's origin, and only pages served from this machine may connect. */
	private static boolean isLocalOrigin(String origin) {
		return origin == null || origin.isEmpty() || origin.equals("null") || LOCAL_ORIGIN.matcher(origin).matches();
	}

	/**
	 * Refuses what a web page from elsewhere could make of a server on loopback: a request whose
	 * Host is not this server (DNS rebinding: a name of the attacker's that resolves to 127.0.0.1
	 * makes the browser treat this server as the attacker's site), and TRACE, which would echo the
	 * request back. Each refusal is one line in the log.
	 */
	private static final class LoopbackGuard extends Handler.Wrapper {
		private static final Pattern LOCAL_HOST = Pattern.compile("(127\\.0\\.0\\.1|localhost|\\[::1\\])(:(\\d+))?");

		LoopbackGuard(Handler handler) {
			super(handler);
		}

		@Override
		public boolean handle(Request request, Response response, Callback callback) throws Exception {
			if ("TRACE".equalsIgnoreCase(request.getMethod())) {
				REFUSALS.warn("refused a TRACE request");
				Response.writeError(request, response, callback, 405, "TRACE is not served");
				return true;
			}
			String host = request.getHeaders().get("Host");
			var local = host == null ? null : LOCAL_HOST.matcher(host);
			if (local == null || !local.matches() || (local.group(3) != null && Integer.parseInt(local.group(3)) != Request.getLocalPort(request))) {
				REFUSALS.warn("refused a request for host " + (host == null ? "(none)" : Reasons.quote(host)) + ": this server answers only to 127.0.0.1 and localhost");
				Response.writeError(request, response, callback, 403, "this server answers only to 127.0.0.1 and localhost");
				return true;
			}
			return super.handle(request, response, callback);
		}
	}

	private static final org.apache.logging.log4j.Logger REFUSALS = org.apache.logging.log4j.LogManager.getLogger("org.kse.diagram");

	private static final Pattern LOCAL_ORIGIN = Pattern.compile("(https?|file)://(127\\.0\\.0\\.1|localhost|\\[::1\\])(:\\d+)?");

	public int port() {
		return ((ServerConnector) jetty.getConnectors()[0]).getLocalPort();
	}

	public String token() {
		return token;
	}

	/** The page that edits this model (a path relative to the served folder), token included. */
	public URI page(String model) {
		return URI.create("http://127.0.0.1:" + port() + "/?token=" + token + "&model=" + java.net.URLEncoder.encode(model, java.nio.charset.StandardCharsets.UTF_8));
	}

	/** The statecharts in the served folder, relative to it. */
	public java.util.List<String> models() throws java.io.IOException {
		return ModelListServlet.models(served);
	}

	/** Where a client connects, token included. */
	public URI uri() {
		return URI.create("ws://127.0.0.1:" + port() + PATH + "?token=" + token);
	}

	@Override
	public void close() throws Exception {
		jetty.stop();
	}
}
