package org.kse.ui.statechart.replay;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.emf.edit.domain.EditingDomain;
import org.eclipse.swt.SWT;
import org.eclipse.swt.SWTError;
import org.eclipse.swt.browser.Browser;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.eclipse.ui.IEditorInput;
import org.eclipse.ui.IEditorSite;
import org.eclipse.ui.IURIEditorInput;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.part.EditorPart;
import org.kse.diagram.server.StatechartSources;
import org.kse.diagram.server.websocket.MatchLogServlet;
import org.kse.model.StatechartResources;
import org.kse.model.edit.StatechartEdits;
import org.kse.model.statechart.Model;
import org.kse.ui.statechart.BehaviourModels;
import org.kse.ui.statechart.diagram.WorkspaceDiagramServer;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import com.google.gson.JsonParseException;

/**
 * The Match Replay editor of a match log ({@code .jsonl}, docs/match-log.md): the diagram page's
 * replay (the field at t, the timeline, play, speed, frame steps, the selected robot's statechart
 * with its active states) in an SWT Browser, served by the {@link WorkspaceDiagramServer} as the
 * statechart editor's Diagram tab is.
 * <p>
 * That server serves the workspace folder's logs by their path in it ({@link MatchLogServlet}'s
 * rules) and opens no model that is not lent to it. So the editor reads the log's first line for
 * its robots' behaviours, finds each {@code <behaviour>.stct} in the open projects, lends a
 * read-only copy of the model (no editor is opened; while one has the file, the page gets its
 * model) and names them to the page ({@code &models=Goalie:editor-KEY/Goalie.stct,…}). What is wrong with the
 * log itself (cut short, another version, not a log) the page says; a log the server cannot send
 * (outside the workspace folder, a path it refuses) is said here, in place of the page.
 */
public final class ReplayEditor extends EditorPart {

	public static final String ID = "org.kse.ui.statechart.replayEditor";

	/** The longest first line read for the behaviours (a 5-against-5 match line is under 1 kB). */
	private static final int MAX_HEADER = 1 << 20;

	/** A behaviour as the page's &models= can carry it (no ':' or ','): the generator's names are identifiers. */
	private static final Pattern BEHAVIOUR = Pattern.compile("[A-Za-z_][A-Za-z0-9_]*");

	/** A model lent by replays, and by how many open replay editors (the last one closed takes it back). */
	private static final class Lent {
		final WorkspaceDiagramServer.Host host;
		int users;

		Lent(WorkspaceDiagramServer.Host host) {
			this.host = host;
		}
	}

	/** The models lent by replay editors, on the UI thread only. */
	private static final Map<Path, Lent> LENT = new HashMap<>();

	private Composite control;
	private Browser browser;
	private String problem;
	private final List<String> notices = new ArrayList<>();
	/** The page's name of each behaviour's model, as passed in &models=. */
	private final Map<String, String> models = new LinkedHashMap<>();
	/** What this editor holds of LENT. */
	private final List<Path> holding = new ArrayList<>();

	@Override
	public void init(IEditorSite site, IEditorInput input) throws PartInitException {
		if (!(input instanceof IURIEditorInput)) {
			throw new PartInitException("The match replay opens files (a .jsonl match log), not " + input.getName());
		}
		setSite(site);
		setInput(input);
		setPartName(input.getName());
	}

	@Override
	public void createPartControl(Composite parent) {
		control = new Composite(parent, SWT.NONE);
		GridLayout layout = new GridLayout(1, false);
		layout.marginWidth = 0;
		layout.marginHeight = 0;
		control.setLayout(layout);
		Path log = file();
		Path folder = WorkspaceDiagramServer.folder();
		String name = log == null ? null : MatchLogServlet.replayName(folder, log);
		if (name == null) {
			say(whyNotServed(log, folder));
			return;
		}
		setTitleToolTip(log.toString());
		lend(behaviours(log));
		notices.forEach(this::message);
		try {
			Map<String, String> query = new LinkedHashMap<>();
			query.put("replay", name);
			query.put("models", models.entrySet().stream().map(entry -> entry.getKey() + ":" + entry.getValue()).collect(Collectors.joining(",")));
			URI page = WorkspaceDiagramServer.page(query);
			browser = new Browser(control, SWT.NONE);
			browser.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
			browser.setUrl(page.toString());
		} catch (SWTError | Exception e) {
			if (browser != null) {
				browser.dispose();
				browser = null;
			}
			say("The replay cannot be shown here: " + e.getMessage() + ". kse serve replays it in a web browser (how-tos: Replay a match).");
		}
	}

	/** The log's file on this computer, or null (an editor input of another file system). */
	private Path file() {
		URI uri = ((IURIEditorInput) getEditorInput()).getURI();
		return uri != null && "file".equals(uri.getScheme()) ? Path.of(uri) : null;
	}

	private static String whyNotServed(Path log, Path folder) {
		if (log == null) {
			return "This log is not a file on this computer: the replay reads match logs of the workspace folder (" + folder + ").";
		}
		if (!log.toAbsolutePath().normalize().startsWith(folder)) {
			return log + " lies outside the workspace folder " + folder + ", and the workbench's diagram server sends the replay page only match logs"
					+ " inside it (a linked project's files stay where they are). Copy the log into a project in the workspace folder,"
					+ " or replay it with kse serve " + log.getParent() + " (how-tos: Replay a match).";
		}
		return folder.relativize(log.toAbsolutePath().normalize()) + " cannot be sent to the replay page: the diagram server sends match logs"
				+ " whose path in the workspace folder has only letters, digits, '.', '_', '-' and '/', and no hidden folder (a name starting"
				+ " with '.'), and that are regular files inside it (links followed). Rename the folder or file, or copy the log.";
	}

	private void say(String text) {
		problem = text;
		message(text);
		control.layout(true);
	}

	private void message(String text) {
		Label label = new Label(control, SWT.WRAP);
		label.setText(text);
		GridData data = new GridData(SWT.FILL, SWT.TOP, true, false);
		data.horizontalIndent = 8;
		data.verticalIndent = 8;
		label.setLayoutData(data);
	}

	/**
	 * The robots' behaviours from the log's first line (a {@code match} record), in order; none when
	 * the line is not one: then the page, which reads the whole log, says what the file is.
	 */
	static Set<String> behaviours(Path log) {
		Set<String> behaviours = new LinkedHashSet<>();
		try (InputStream in = Files.newInputStream(log)) {
			ByteArrayOutputStream line = new ByteArrayOutputStream();
			for (int b = in.read(); b >= 0 && b != '\n' && line.size() < MAX_HEADER; b = in.read()) {
				line.write(b);
			}
			JsonElement header = JsonParser.parseString(line.toString(StandardCharsets.UTF_8));
			if (!header.isJsonObject() || !"match".equals(text(header.getAsJsonObject(), "type")) || !header.getAsJsonObject().has("teams")
					|| !header.getAsJsonObject().get("teams").isJsonArray()) {
				return behaviours;
			}
			for (JsonElement team : header.getAsJsonObject().getAsJsonArray("teams")) {
				if (!team.isJsonObject() || !team.getAsJsonObject().has("players") || !team.getAsJsonObject().get("players").isJsonArray()) {
					continue;
				}
				for (JsonElement player : team.getAsJsonObject().getAsJsonArray("players")) {
					String behaviour = player.isJsonObject() ? text(player.getAsJsonObject(), "behaviour") : null;
					if (behaviour != null && BEHAVIOUR.matcher(behaviour).matches()) {
						behaviours.add(behaviour);
					}
				}
			}
		} catch (IOException | JsonParseException | IllegalStateException e) {
			// not a log, or not readable: the page tells, from what the server sends
		}
		return behaviours;
	}

	private static String text(JsonObject object, String member) {
		JsonElement value = object.get(member);
		return value != null && value.isJsonPrimitive() && value.getAsJsonPrimitive().isString() ? value.getAsString() : null;
	}

	/**
	 * Lends the model of each behaviour found in the open projects, read-only (the first replay that
	 * shows it; the server gives pages the editor's model instead while one has the file); a
	 * behaviour without a model is left out of &models=, and the page says so when its robot is selected.
	 */
	private void lend(Set<String> behaviours) {
		for (String behaviour : behaviours) {
			IFile model = BehaviourModels.find(behaviour);
			URI location = model == null ? null : model.getLocationURI();
			if (location == null || !"file".equals(location.getScheme())) {
				continue;
			}
			Path file = Path.of(location).toAbsolutePath().normalize();
			if (!LENT.containsKey(file)) {
				try {
					EditingDomain domain = StatechartEdits.newDomain();
					Lent lent = new Lent(new ReadOnly(StatechartResources.load(domain.getResourceSet(), file), domain));
					WorkspaceDiagramServer.lend(file, lent.host);
					LENT.put(file, lent);
				} catch (IOException | RuntimeException e) {
					notices.add(model.getFullPath() + " cannot be read (" + e.getMessage() + "): the robots playing " + behaviour
							+ " are shown without their statechart.");
					continue;
				}
			}
			LENT.get(file).users++;
			holding.add(file);
			models.put(behaviour, WorkspaceDiagramServer.name(file));
		}
	}

	/**
	 * A model lent to a replay's page: the page shows it read-only, so there is nothing to save; it
	 * is the file as it was when the replay opened.
	 */
	private static final class ReadOnly implements WorkspaceDiagramServer.Host {
		private final Model model;
		private final EditingDomain domain;
		private final List<StatechartSources.NotationWriter> participants = new CopyOnWriteArrayList<>();

		ReadOnly(Model model, EditingDomain domain) {
			this.model = model;
			this.domain = domain;
		}

		@Override
		public Model model() {
			return model;
		}

		@Override
		public EditingDomain domain() {
			return domain;
		}

		@Override
		public void save() {
			// the replayed page is read-only: it never asks to save
		}

		@Override
		public List<StatechartSources.NotationWriter> saveParticipants() {
			return participants;
		}
	}

	/** The browser showing the replay; null when the editor shows a message instead. */
	public Browser browser() {
		return browser;
	}

	/** Why the replay is not shown (the message in its place), or null. */
	public String problem() {
		return problem;
	}

	/** Models that could not be read (the page is shown without their charts). */
	public List<String> notices() {
		return List.copyOf(notices);
	}

	/** The page's name of each behaviour's model (&models=). */
	public Map<String, String> models() {
		return Map.copyOf(models);
	}

	@Override
	public void dispose() {
		for (Path file : holding) {
			Lent lent = LENT.get(file);
			if (lent != null && --lent.users == 0) {
				LENT.remove(file);
				WorkspaceDiagramServer.unlend(file, lent.host);
			}
		}
		holding.clear();
		super.dispose();
	}

	@Override
	public void doSave(IProgressMonitor monitor) {
		// a replay changes nothing
	}

	@Override
	public void doSaveAs() {
		// a replay changes nothing
	}

	@Override
	public boolean isDirty() {
		return false;
	}

	@Override
	public boolean isSaveAsAllowed() {
		return false;
	}

	@Override
	public void setFocus() {
		if (browser != null && !browser.isDisposed()) {
			browser.setFocus();
		} else if (control != null) {
			control.setFocus();
		}
	}
}
