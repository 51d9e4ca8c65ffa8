package org.kse.testing;

import java.io.IOException;
import java.net.InetAddress;
import java.net.Proxy;
import java.net.ProxySelector;
import java.net.ServerSocket;
import java.net.SocketAddress;
import java.net.URI;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The network as hostile input could make the code under test reach it: an address on loopback
 * that answers nothing and counts the connections made to it (hostile inputs point at it), and
 * a proxy selector that sees every URL connection whatever its host. Closing restores the
 * former proxy selector.
 */
public final class NetworkTrap implements AutoCloseable {

	private final ServerSocket trap = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
	private final AtomicInteger connections = new AtomicInteger();
	private final ProxySelector previous = ProxySelector.getDefault();
	private final List<String> looked = new ArrayList<>();

	public NetworkTrap() throws IOException {
		Thread listener = new Thread(() -> {
			while (!trap.isClosed()) {
				try {
					trap.accept().close();
					connections.incrementAndGet();
				} catch (IOException closed) {
					return;
				}
			}
		}, "kse-network-trap");
		listener.setDaemon(true);
		listener.start();
		ProxySelector.setDefault(new ProxySelector() {
			@Override
			public List<Proxy> select(URI uri) {
				synchronized (looked) {
					looked.add(String.valueOf(uri));
				}
				return List.of(Proxy.NO_PROXY);
			}

			@Override
			public void connectFailed(URI uri, SocketAddress address, IOException e) {
				// the trap answers nothing: a failure is what it is for
			}
		});
	}

	/** The trap's address as a URL, for hostile inputs to name. */
	public String remote() {
		return "http://127.0.0.1:" + port();
	}

	public String port() {
		return String.valueOf(trap.getLocalPort());
	}

	/** What reached for the network since the last call (connections, URLs), or null when nothing did. */
	public String take() {
		synchronized (looked) {
			if (connections.get() == 0 && looked.isEmpty()) {
				return null;
			}
			String reached = "reached for the network (" + connections.getAndSet(0) + " connections, URLs " + looked + ")";
			looked.clear();
			return reached;
		}
	}

	@Override
	public void close() throws IOException {
		ProxySelector.setDefault(previous);
		trap.close();
	}
}
