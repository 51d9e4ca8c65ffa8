package org.kse.diagram.server.websocket;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.util.List;

import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;
import jakarta.websocket.Session;

/**
 * This server's session token as its resources check it: a request or WebSocket connection must
 * present it as {@code ?token=…}; a request without it is answered 403, a connection is closed
 * (1008) by its endpoint.
 */
final class SessionToken {

	static final String PARAMETER = "token";
	static final String REFUSAL = "the session token is missing or wrong";

	private final byte[] token;

	SessionToken(String token) {
		this.token = token.getBytes(StandardCharsets.UTF_8);
	}

	/** Whether {@code presented} (null: none) is the token; in constant time, so a page cannot guess it byte by byte from the delays. */
	boolean isPresented(String presented) {
		return presented != null && MessageDigest.isEqual(token, presented.getBytes(StandardCharsets.UTF_8));
	}

	/** True when {@code request} presents the token; otherwise answers it 403 and returns false. */
	boolean admits(HttpServletRequest request, HttpServletResponse response) throws IOException {
		if (isPresented(request.getParameter(PARAMETER))) {
			return true;
		}
		response.sendError(HttpServletResponse.SC_FORBIDDEN, REFUSAL);
		return false;
	}

	/** Whether the query of the WebSocket {@code session} presents the token, exactly once. */
	boolean isPresentedIn(Session session) {
		List<String> presented = session.getRequestParameterMap().get(PARAMETER);
		return presented != null && presented.size() == 1 && isPresented(presented.get(0));
	}
}
