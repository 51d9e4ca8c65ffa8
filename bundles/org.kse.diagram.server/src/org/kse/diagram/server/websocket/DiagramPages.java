package org.kse.diagram.server.websocket;

import java.net.URL;

import org.osgi.framework.Bundle;
import org.osgi.framework.FrameworkUtil;

/** Where the built diagram client (bundle {@code org.kse.diagram.client}) keeps its page. */
public final class DiagramPages {

	public static final String CLIENT_BUNDLE = "org.kse.diagram.client";

	private DiagramPages() {
	}

	/** The folder URL of the installed client's page, or null when the client is not installed. */
	public static URL builtIn() {
		Bundle self = FrameworkUtil.getBundle(DiagramPages.class);
		if (self == null || self.getBundleContext() == null) {
			return onClassPath();
		}
		for (Bundle bundle : self.getBundleContext().getBundles()) {
			if (CLIENT_BUNDLE.equals(bundle.getSymbolicName())) {
				URL index = bundle.getEntry("dist/index.html");
				return index == null ? null : bundle.getEntry("dist/");
			}
		}
		return null;
	}

	/**
	 * The page when KSE runs on a plain class path (the kse command's launcher): the client's jar
	 * is on it, and its bundled script has a name no other jar uses.
	 */
	private static URL onClassPath() {
		URL script = DiagramPages.class.getClassLoader().getResource("dist/kse-diagram.js");
		if (script == null) {
			return null;
		}
		String address = script.toExternalForm();
		try {
			return java.net.URI.create(address.substring(0, address.lastIndexOf('/') + 1)).toURL();
		} catch (java.net.MalformedURLException | IllegalArgumentException e) {
			return null;
		}
	}
}
