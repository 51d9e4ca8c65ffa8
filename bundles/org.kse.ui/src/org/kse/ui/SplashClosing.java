package org.kse.ui;

import java.awt.SplashScreen;

import org.eclipse.osgi.service.runnable.StartupMonitor;

/**
 * Takes down the splash screen the start scripts show with the JVM's {@code -splash:} option
 * (there is no native launcher to show Eclipse's own), once the workbench window is up.
 *
 * <p>The application container tells every {@link StartupMonitor} service when the application
 * runs; this one is a declarative services component, so the splash closes without KSE's bundle
 * being started early.
 */
public final class SplashClosing implements StartupMonitor {

	@Override
	public void update() {
		// progress is not drawn on the JVM's splash
	}

	@Override
	public void applicationRunning() {
		try {
			SplashScreen splash = SplashScreen.getSplashScreen();
			if (splash != null) {
				splash.close();
			}
		} catch (UnsupportedOperationException | IllegalStateException notShown) {
			// started without a splash, or headless (HeadlessException is an UnsupportedOperationException)
		}
	}
}
