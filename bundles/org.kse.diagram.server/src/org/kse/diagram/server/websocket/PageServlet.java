package org.kse.diagram.server.websocket;

import java.io.FileNotFoundException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.URI;
import java.net.URL;
import java.util.Locale;
import java.util.Map;

import jakarta.servlet.http.HttpServlet;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;

/**
 * The diagram client's files (the page, its script, styles and fonts), read from one base URL:
 * a folder, or a folder inside the client bundle. Only names inside the base are served.
 */
final class PageServlet extends HttpServlet {

	private static final long serialVersionUID = 1L;

	private static final Map<String, String> TYPES = Map.of("html", "text/html; charset=utf-8", "js", "text/javascript; charset=utf-8", "css",
			"text/css; charset=utf-8", "svg", "image/svg+xml", "png", "image/png", "ttf", "font/ttf", "woff", "font/woff", "woff2", "font/woff2",
			"map", "application/json");

	private final transient URL base;

	PageServlet(URL base) {
		this.base = base;
	}

	@Override
	protected void doGet(HttpServletRequest request, HttpServletResponse response) throws IOException {
		String path = request.getPathInfo() == null || request.getPathInfo().equals("/") ? "index.html" : request.getPathInfo().substring(1);
		if (!path.matches("[A-Za-z0-9._/-]+") || path.contains("..") || path.startsWith("/")) {
			response.sendError(HttpServletResponse.SC_NOT_FOUND);
			return;
		}
		String extension = path.substring(path.lastIndexOf('.') + 1).toLowerCase(Locale.ROOT);
		URL file;
		try {
			// appended, not resolved: the page may sit in a jar (jar:file:...!/dist/), whose URI is opaque
			file = URI.create(base.toString() + path).toURL();
		} catch (IllegalArgumentException e) {
			response.sendError(HttpServletResponse.SC_NOT_FOUND);
			return;
		}
		try (InputStream in = file.openStream()) {
			response.setContentType(TYPES.getOrDefault(extension, "application/octet-stream"));
			response.setHeader("Cache-Control", "no-cache");
			response.setHeader("X-Content-Type-Options", "nosniff");
			try (OutputStream out = response.getOutputStream()) {
				in.transferTo(out);
			}
		} catch (FileNotFoundException | java.nio.file.NoSuchFileException e) {
			response.sendError(HttpServletResponse.SC_NOT_FOUND);
		}
	}
}
