package org.kse.diagram.server.websocket;

import java.util.List;
import java.util.function.Predicate;
import java.util.function.Supplier;

import jakarta.websocket.Endpoint;
import jakarta.websocket.Extension;
import jakarta.websocket.HandshakeResponse;
import jakarta.websocket.server.HandshakeRequest;
import jakarta.websocket.server.ServerEndpointConfig;

/**
 * Makes each connection's endpoint and answers the handshake questions itself: the Jakarta
 * default configurator is found through {@link java.util.ServiceLoader}, which does not see
 * across OSGi bundles and fails the handshake with an HTTP 500. The endpoints of this server
 * differ only in the pages they accept ({@code origins}).
 */
final class EndpointConfigurator extends ServerEndpointConfig.Configurator {
	private final Supplier<? extends Endpoint> endpoints;
	private final Predicate<String> origins;

	/**
	 * {@code endpoints} makes one connection's endpoint; {@code origins} accepts the Origin header of a
	 * handshake (null or empty when the client is not a browser).
	 */
	EndpointConfigurator(Supplier<? extends Endpoint> endpoints, Predicate<String> origins) {
		this.endpoints = endpoints;
		this.origins = origins;
	}

	@Override
	public <T> T getEndpointInstance(Class<T> endpointClass) {
		return endpointClass.cast(endpoints.get());
	}

	@Override
	public boolean checkOrigin(String origin) {
		return origins.test(origin);
	}

	@Override
	public String getNegotiatedSubprotocol(List<String> supported, List<String> requested) {
		return "";
	}

	@Override
	public List<Extension> getNegotiatedExtensions(List<Extension> installed, List<Extension> requested) {
		return List.of();
	}

	@Override
	public void modifyHandshake(ServerEndpointConfig config, HandshakeRequest request, HandshakeResponse response) {
		// nothing to add: the token travels in the query and is checked when the endpoint opens
	}
}
