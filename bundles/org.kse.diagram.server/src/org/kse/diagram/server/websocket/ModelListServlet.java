package org.kse.diagram.server.websocket;

import java.io.IOException;
import java.util.List;
import java.util.stream.Stream;

import org.kse.diagram.server.ServedFolder;

import com.google.gson.JsonArray;

import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;
import jakarta.servlet.http.HttpServlet;

/** The statecharts of the served folder, as a JSON array of relative paths; only with the session token. */
final class ModelListServlet extends HttpServlet {

	private static final long serialVersionUID = 1L;

	private final transient ServedFolder folder;
	private final transient SessionToken token;

	ModelListServlet(ServedFolder folder, String token) {
		this.folder = folder;
		this.token = new SessionToken(token);
	}

	@Override
	protected void doGet(HttpServletRequest request, HttpServletResponse response) throws IOException {
		if (!token.admits(request, response)) {
			return;
		}
		JsonArray models = new JsonArray();
		for (String model : models(folder)) {
			models.add(model);
		}
		response.setContentType("application/json; charset=utf-8");
		response.setHeader("Cache-Control", "no-store");
		response.getWriter().write(models.toString());
	}

	/** The .stct files under the folder, as sorted relative paths with forward slashes. */
	static List<String> models(ServedFolder folder) throws IOException {
		try (Stream<java.nio.file.Path> files = java.nio.file.Files.walk(folder.root(), 8)) {
			return files.filter(file -> file.getFileName().toString().endsWith(".stct") && java.nio.file.Files.isRegularFile(file))
					.map(file -> folder.root().relativize(file).toString().replace('\\', '/')).filter(path -> !path.startsWith(".") && !path.contains("/."))
					.sorted().toList();
		}
	}
}
