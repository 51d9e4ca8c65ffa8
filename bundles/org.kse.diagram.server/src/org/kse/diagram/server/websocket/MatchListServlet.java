package org.kse.diagram.server.websocket;

import java.io.IOException;

import com.google.gson.JsonArray;

import jakarta.servlet.http.HttpServlet;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;

/**
 * The running matches a page may watch ({@code /matches?token=…}): a JSON array of each match's pid,
 * seed, start and robots with their behaviours, from the discovery folder. Never a match's port or
 * key: the page names a match by its pid and the relay ({@code /monitor?match=PID}) looks them up.
 */
final class MatchListServlet extends HttpServlet {

	static final String PATH = "/matches";

	private static final long serialVersionUID = 1L;

	private final transient SessionToken token;

	MatchListServlet(String token) {
		this.token = new SessionToken(token);
	}

	@Override
	protected void doGet(HttpServletRequest request, HttpServletResponse response) throws IOException {
		if (!token.admits(request, response)) {
			return;
		}
		JsonArray matches = new JsonArray();
		RunningMatches.list().forEach(match -> matches.add(match.toPublicJson()));
		response.setContentType("application/json; charset=utf-8");
		response.setHeader("Cache-Control", "no-store");
		response.getWriter().write(matches.toString());
	}
}
