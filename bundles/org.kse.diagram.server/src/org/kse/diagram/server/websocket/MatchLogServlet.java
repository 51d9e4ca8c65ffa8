package org.kse.diagram.server.websocket;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.kse.diagram.server.ServedFolder;

import com.google.gson.JsonArray;

import jakarta.servlet.http.HttpServlet;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;

/**
 * The match logs ({@code .jsonl}, docs/match-log.md) of the served folder, for the page's replay:
 * {@code GET /logs?token=T} lists them as a JSON array of relative paths, {@code GET /logs/<path>?token=T}
 * sends one as it is on disk. Read-only (GET only) and only with the session token: a log shows
 * what the robots did, and the folder may be a workspace. Names are restricted as the page's files
 * are ({@code [A-Za-z0-9._/-]}, no {@code ..}, no hidden segment) and must resolve, links followed,
 * to a regular file inside the folder.
 */
public final class MatchLogServlet extends HttpServlet {

	private static final long serialVersionUID = 1L;

	/** Where the servlet is mapped ({@code PATH/*}, which also matches {@code PATH} alone). */
	static final String PATH = "/logs";

	static final String EXTENSION = ".jsonl";

	private static final Pattern NAME = Pattern.compile("[A-Za-z0-9._/-]+");

	private final transient ServedFolder folder;
	private final transient SessionToken token;

	MatchLogServlet(ServedFolder folder, String token) {
		this.folder = folder;
		this.token = new SessionToken(token);
	}

	@Override
	protected void doGet(HttpServletRequest request, HttpServletResponse response) throws IOException {
		if (!token.admits(request, response)) {
			return;
		}
		response.setHeader("Cache-Control", "no-store");
		response.setHeader("X-Content-Type-Options", "nosniff");
		String info = request.getPathInfo();
		if (info == null || info.equals("/")) {
			JsonArray logs = new JsonArray();
			for (String log : logs(folder)) {
				logs.add(log);
			}
			response.setContentType("application/json; charset=utf-8");
			response.getWriter().write(logs.toString());
			return;
		}
		Path file = resolve(folder, info.substring(1));
		if (file == null) {
			response.sendError(HttpServletResponse.SC_NOT_FOUND, "no such match log in the served folder");
			return;
		}
		try (InputStream in = Files.newInputStream(file)) {
			// a log being written grows while it is sent: the length is not known in advance
			response.setContentType("application/x-ndjson; charset=utf-8");
			try (OutputStream out = response.getOutputStream()) {
				in.transferTo(out);
			}
		} catch (NoSuchFileException e) {
			response.sendError(HttpServletResponse.SC_NOT_FOUND, "no such match log in the served folder");
		}
	}

	/**
	 * The log a page names, or null when the name is not one of a log of the folder: another
	 * extension, characters outside the page's set, {@code ..} or a hidden segment, a file that is
	 * missing, not regular, or (links followed) outside the folder.
	 */
	static Path resolve(ServedFolder folder, String name) {
		if (!NAME.matcher(name).matches() || !name.endsWith(EXTENSION) || name.startsWith("/")) {
			return null;
		}
		for (String segment : name.split("/")) {
			if (segment.isEmpty() || segment.startsWith(".")) {
				return null;
			}
		}
		Path file = folder.root().resolve(name).normalize();
		try {
			if (!file.startsWith(folder.root()) || !Files.isRegularFile(file) || !file.toRealPath().startsWith(folder.root().toRealPath())) {
				return null;
			}
		} catch (IOException e) {
			return null;
		}
		return file;
	}

	/**
	 * The name by which a page of the server serving {@code folder} replays {@code file}
	 * ({@code ?replay=<name>}, sent by {@code /logs/<name>}), or null when the server would not send
	 * it (the rules of {@link #resolve}): a host that shows the page (the workbench's replay editor)
	 * asks here rather than repeating the rules.
	 */
	public static String replayName(Path folder, Path file) {
		ServedFolder served = new ServedFolder(folder);
		Path absolute = file.toAbsolutePath().normalize();
		if (!absolute.startsWith(served.root())) {
			return null;
		}
		String name = served.root().relativize(absolute).toString().replace(java.io.File.separatorChar, '/');
		return resolve(served, name) == null ? null : name;
	}

	/** The .jsonl files under the folder (8 levels deep at most), as sorted relative paths with forward slashes. */
	static List<String> logs(ServedFolder folder) throws IOException {
		try (Stream<Path> files = Files.walk(folder.root(), 8)) {
			return files.filter(file -> file.getFileName().toString().endsWith(EXTENSION) && Files.isRegularFile(file))
					.map(file -> folder.root().relativize(file).toString().replace('\\', '/'))
					.filter(path -> !path.startsWith(".") && !path.contains("/.") && NAME.matcher(path).matches()).sorted().toList();
		}
	}
}
