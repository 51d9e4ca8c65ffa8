package org.kse.ui.statechart.diagram;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.swt.SWT;
import org.eclipse.swt.SWTError;
import org.eclipse.swt.browser.Browser;
import org.eclipse.swt.browser.BrowserFunction;
import org.eclipse.swt.layout.FillLayout;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.kse.model.statechart.Model;

import com.google.gson.Gson;
import com.google.gson.JsonArray;
import com.google.gson.JsonParseException;
import com.google.gson.JsonParser;

/**
 * The statechart diagram inside an editor: the KSE diagram page (the same one {@code kse serve}
 * shows a browser) in an SWT Browser, served by the {@link WorkspaceDiagramServer}. The page's
 * selection is reported as model elements; the editor's selection is shown on the page.
 */
public final class DiagramPage {

	private static final Gson JSON = new Gson();

	/** The page's id of the model itself (the diagram's root). */
	private static final String ROOT_ID = "statechart";

	private final Composite control;
	private final Browser browser;
	private final String problem;
	private final Path file;

	/**
	 * Creates the page for {@code file}; {@code selected} hears the elements selected on it.
	 * Without a browser engine (or a diagram client) the page says why and {@link #isAvailable()} is false.
	 */
	public DiagramPage(Composite parent, Path file, java.util.function.Supplier<Model> model, Consumer<List<EObject>> selected) {
		this.file = file;
		control = new Composite(parent, SWT.NONE);
		control.setLayout(new FillLayout());
		Browser created = null;
		String failure = null;
		try {
			created = new Browser(control, SWT.NONE);
			created.setUrl(WorkspaceDiagramServer.page(file).toString());
			new BrowserFunction(created, "kseHostSelection") {
				@Override
				public Object function(Object[] arguments) {
					if (arguments.length == 1 && arguments[0] instanceof String json) {
						selected.accept(elements(model.get(), ids(json)));
					}
					return null;
				}
			};
			// the page lost its connection and asks where to open anew (a new server if the old one is gone); the model is the editor's, so nothing is lost
			new BrowserFunction(created, "kseHostReconnect") {
				@Override
				public Object function(Object[] arguments) {
					try {
						return WorkspaceDiagramServer.page(file).toString();
					} catch (Exception e) {
						return null; // the page says it cannot reconnect
					}
				}
			};
		} catch (SWTError | Exception e) {
			if (created != null) {
				created.dispose();
				created = null;
			}
			failure = "The diagram cannot be shown here: " + e.getMessage() + ". The Tree tab edits the statechart.";
			Label message = new Label(control, SWT.WRAP);
			message.setText(failure);
		}
		browser = created;
		problem = failure;
	}

	public Composite getControl() {
		return control;
	}

	/** The browser that shows the page; null when the diagram cannot be shown. */
	public Browser getBrowser() {
		return browser;
	}

	public boolean isAvailable() {
		return browser != null;
	}

	/** Why the diagram cannot be shown, or null. */
	public String getProblem() {
		return problem;
	}

	/** Opens the page again: a new session on the editor's current model (after Revert, or a lost connection). */
	public void reload() {
		if (browser != null && !browser.isDisposed()) {
			try {
				browser.setUrl(WorkspaceDiagramServer.page(file).toString());
			} catch (Exception e) {
				browser.setText("<p>" + e.getMessage() + "</p>");
			}
		}
	}

	/** Selects these elements on the page (when it is ready). */
	public void select(List<?> elements) {
		if (browser == null || browser.isDisposed()) {
			return;
		}
		List<String> ids = new ArrayList<>();
		for (Object element : elements) {
			String id = id(element);
			if (id != null) {
				ids.add(id);
			}
		}
		browser.execute("window.kse && window.kse.ready.then(() => window.kse.select(" + JSON.toJson(ids) + "))");
	}

	/** Runs a script in the page and returns its result (for tests and the editor's commands). */
	public Object evaluate(String script) {
		return browser == null || browser.isDisposed() ? null : browser.evaluate(script);
	}

	private static String id(Object element) {
		if (element instanceof Model) {
			return ROOT_ID;
		}
		if (element instanceof EObject object && object.eResource() != null) {
			return object.eResource().getURIFragment(object);
		}
		return null;
	}

	/** The ids the page reports (a JSON array of strings); none when it is not one. */
	private static List<String> ids(String json) {
		List<String> ids = new ArrayList<>();
		try {
			if (JsonParser.parseString(json) instanceof JsonArray array) {
				array.forEach(each -> {
					if (each.isJsonPrimitive()) {
						ids.add(each.getAsString());
					}
				});
			}
		} catch (JsonParseException e) {
			// not from our page: nothing is selected
		}
		return ids;
	}

	private static List<EObject> elements(Model model, List<String> ids) {
		List<EObject> elements = new ArrayList<>();
		Resource resource = model == null ? null : model.eResource();
		for (String id : ids) {
			int hash = id.indexOf('#');
			String path = hash < 0 ? id : id.substring(0, hash);
			EObject element = ROOT_ID.equals(path) ? model : resource == null ? null : resource.getEObject(path);
			if (element != null && !elements.contains(element)) {
				elements.add(element);
			}
		}
		return elements;
	}
}
