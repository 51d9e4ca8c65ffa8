package org.kse.ui.statechart.diagram;

import java.net.URI;
import java.net.URL;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Supplier;

import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.emf.edit.domain.EditingDomain;
import org.eclipse.swt.widgets.Display;
import org.kse.diagram.server.StatechartSources;
import org.kse.diagram.server.websocket.DiagramPages;
import org.kse.diagram.server.websocket.DiagramSocketServer;
import org.kse.model.statechart.Model;

/**
 * The workbench's diagram server: one per workbench, started when the first diagram is shown,
 * on a loopback port with its own random token, serving the statecharts open in statechart
 * editors (wherever their projects lie), each named by a random key. A diagram page gets the
 * model of the editor that shows it (see {@link Host}), so that the page, the tree and the
 * Properties view edit one model on one command stack, on the UI thread.
 */
public final class WorkspaceDiagramServer {

	/** What an editor lends the diagram sessions of its file. */
	public interface Host {
		Model model();

		EditingDomain domain();

		/** Saves the model, then runs the editor's save participants (the diagrams' notations). */
		void save();

		List<StatechartSources.NotationWriter> saveParticipants();
	}

	/** How a page names the file of an open editor: {@code <prefix><random key>/<file name>}. */
	private static final String EDITOR_PREFIX = "editor-";

	private static DiagramSocketServer server;
	/** The port of the last server: one started again takes it when it is free, so that its pages keep their origin. */
	private static int lastPort;
	/** What the pages of one model share (its layout), for as long as the model lives: a page that reconnects finds it. */
	private static final Map<Model, Map<Class<?>, Object>> shared = java.util.Collections.synchronizedMap(new java.util.WeakHashMap<>());
	private static final Map<Path, Host> hosts = new ConcurrentHashMap<>();
	/** Read-only copies lent by replays ({@link #lend}): a page gets one only while no editor has the file. */
	private static final Map<Path, Host> copies = new ConcurrentHashMap<>();
	/** The random key of each file lent, by which its page names it: a page opens only files open in an editor. */
	private static final Map<String, Path> keys = new ConcurrentHashMap<>();

	private WorkspaceDiagramServer() {
	}

	/** Lends the model of {@code file} to the diagram sessions until {@link #unregister}. */
	public static void register(Path file, Host host) {
		hosts.put(key(file), host);
		keep(file);
	}

	public static void unregister(Path file, Host host) {
		if (hosts.remove(key(file), host)) {
			release(file);
		}
	}

	/**
	 * Lends a read-only copy of the model of {@code file} (a replay's chart) until {@link #unlend}:
	 * pages get it while no editor has the file, the editor's model while one has. The file keeps
	 * its name ({@link #name}) as long as either lends it, so that an editor opened and closed
	 * meanwhile does not take the replay's chart away.
	 */
	public static void lend(Path file, Host copy) {
		copies.put(key(file), copy);
		keep(file);
	}

	public static void unlend(Path file, Host copy) {
		if (copies.remove(key(file), copy)) {
			release(file);
		}
	}

	private static void keep(Path file) {
		if (!keys.containsValue(key(file))) {
			byte[] random = new byte[16];
			new java.security.SecureRandom().nextBytes(random);
			keys.put(java.util.HexFormat.of().formatHex(random), key(file));
		}
	}

	/** Forgets the file's name once nothing lends it: a page opens only files lent. */
	private static void release(Path file) {
		if (!hosts.containsKey(key(file)) && !copies.containsKey(key(file))) {
			keys.values().remove(key(file));
		}
	}

	/** The editor's model of the file, else a replay's copy, else null. */
	private static Host host(Path file) {
		Host host = hosts.get(key(file));
		return host != null ? host : copies.get(key(file));
	}

	private static Path key(Path file) {
		return file.toAbsolutePath().normalize();
	}

	/** How a page names a lent file ({@code editor-KEY/<file name>}, see {@link #page(Path)}), or null when it is not lent. */
	public static String name(Path file) {
		return keys.entrySet().stream().filter(entry -> entry.getValue().equals(key(file))).map(entry -> EDITOR_PREFIX + entry.getKey() + "/" + file.getFileName())
				.findFirst().orElse(null);
	}

	/** The folder the server serves besides the lent models (its match logs): the workspace's. */
	public static Path folder() {
		return Path.of(ResourcesPlugin.getWorkspace().getRoot().getLocationURI()).toAbsolutePath().normalize();
	}

	/**
	 * The page with the parameters {@code query} (each value encoded here) after the token, e.g. a
	 * replay's {@code replay=<log>}, starting the server when needed.
	 */
	public static synchronized URI page(Map<String, String> query) throws Exception {
		DiagramSocketServer started = server();
		StringBuilder url = new StringBuilder("http://127.0.0.1:").append(started.port()).append("/?token=").append(started.token());
		query.forEach((name, value) -> url.append('&').append(name).append('=').append(java.net.URLEncoder.encode(value, java.nio.charset.StandardCharsets.UTF_8)));
		return URI.create(url.toString());
	}

	/**
	 * The page that shows {@code file}, open in an editor (a project may lie outside the
	 * workspace folder), starting the server when needed.
	 */
	public static synchronized URI page(Path file) throws Exception {
		DiagramSocketServer started = server();
		String name = name(file);
		if (name == null) {
			throw new IllegalStateException(file.getFileName() + " is not open in a statechart editor");
		}
		return started.page(name);
	}

	/** The server, started when needed. */
	private static synchronized DiagramSocketServer server() throws Exception {
		if (server == null) {
			URL pages = DiagramPages.builtIn();
			if (pages == null) {
				throw new IllegalStateException("the diagram client (bundle " + DiagramPages.CLIENT_BUNDLE + ") is not installed");
			}
			Path workspace = folder();
			EditorSources sources = new EditorSources(Display.getCurrent());
			if (lastPort == 0) {
				Runtime.getRuntime().addShutdownHook(new Thread(WorkspaceDiagramServer::stop, "kse-diagram-server-stop"));
			}
			try {
				server = DiagramSocketServer.start(workspace, lastPort, pages, sources);
			} catch (java.io.IOException e) {
				server = DiagramSocketServer.start(workspace, 0, pages, sources); // the former port is taken now
			}
			lastPort = server.port();
		}
		return server;
	}

	/**
	 * Stops the server (the workbench ends, or a test takes the connection away): its pages lose
	 * their connection and ask their editors to open them again, on a server started anew.
	 */
	public static synchronized void stop() {
		if (server != null) {
			try {
				server.close();
			} catch (Exception e) {
				// the JVM is ending: nothing is left to tell
			}
			server = null;
		}
	}

	/** Hands out the model of the editor that holds a file, named by the key the editor registered. */
	private static final class EditorSources implements StatechartSources {
		private final Display display;

		EditorSources(Display display) {
			this.display = display;
		}

		/** A file open in an editor, by its key; nothing else. */
		@Override
		public Path locate(String requested, org.kse.diagram.server.ServedFolder folder) {
			int slash = requested == null || !requested.startsWith(EDITOR_PREFIX) ? -1 : requested.indexOf('/');
			Path file = slash < 0 ? null : keys.get(requested.substring(EDITOR_PREFIX.length(), slash));
			if (file == null || !file.getFileName().toString().equals(requested.substring(slash + 1))) {
				throw new IllegalArgumentException("refused: " + requested + " is not open in a statechart editor");
			}
			return file;
		}

		@Override
		public Source open(Path file) throws java.io.IOException {
			Host host = host(file);
			if (host == null) {
				throw new java.io.IOException("its editor was closed");
			}
			return new Source() {
				/** This session's notation writer among the editor's save participants. */
				private NotationWriter registered;

				@Override
				public Model model() {
					return host.model();
				}

				@Override
				public EditingDomain domain() {
					return host.domain();
				}

				@Override
				public <T> T access(Supplier<T> access) {
					if (display.isDisposed()) {
						throw new IllegalStateException("the workbench has closed");
					}
					// on the UI thread already, it runs at once; what it throws is thrown here
					return display.syncCall(access::get);
				}

				/** The editor's Save, which writes the notation through the participant {@link #onSave} registered. */
				@Override
				public <T> T shared(Class<T> kind, Supplier<T> create) {
					Map<Class<?>, Object> ofModel = shared.computeIfAbsent(host.model(), model -> new ConcurrentHashMap<>());
					return kind.cast(ofModel.computeIfAbsent(kind, any -> create.get()));
				}

				@Override
				public void save(NotationWriter notation) {
					access(() -> {
						host.save();
						return null;
					});
				}

				@Override
				public void onSave(NotationWriter notation) {
					close();
					registered = notation;
					host.saveParticipants().add(notation);
				}

				@Override
				public void close() {
					if (registered != null) {
						host.saveParticipants().remove(registered);
						registered = null;
					}
				}
			};
		}
	}
}
