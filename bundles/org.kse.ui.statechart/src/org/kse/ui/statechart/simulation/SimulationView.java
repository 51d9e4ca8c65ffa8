package org.kse.ui.statechart.simulation;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalLong;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.stream.Collectors;

import org.eclipse.core.resources.IContainer;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IFolder;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.jface.bindings.keys.KeyStroke;
import org.eclipse.jface.bindings.keys.ParseException;
import org.eclipse.jface.fieldassist.ContentProposalAdapter;
import org.eclipse.jface.fieldassist.TextContentAdapter;
import org.eclipse.jface.resource.JFaceResources;
import org.eclipse.jface.window.Window;
import org.eclipse.swt.SWT;
import org.eclipse.swt.SWTError;
import org.eclipse.swt.browser.Browser;
import org.eclipse.swt.browser.ProgressAdapter;
import org.eclipse.swt.browser.ProgressEvent;
import org.eclipse.swt.custom.SashForm;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Group;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Spinner;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableColumn;
import org.eclipse.swt.widgets.TableItem;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.IWorkbenchPartReference;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.ide.IDE;
import org.eclipse.ui.part.ViewPart;
import org.kse.messages.MessageCatalog;
import org.kse.messages.MessageType;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.simulation.SimulationException;
import org.kse.simulation.SimulationSession;
import org.kse.simulation.SimulationSession.Result;
import org.kse.simulation.SimulatorBuilder;
import org.kse.ui.ModelFiles;
import org.kse.ui.statechart.diagram.WorkspaceDiagramServer;
import org.kse.ui.statechart.editor.StatechartEditor;

/**
 * The Simulation view: a statechart run by its simulator (KSE > Simulate), on the engine a robot
 * runs. The diagram (the editor's diagram page, read-only, {@code &simulation=1}) outlines the
 * active states and marks the transitions the last step took (a press of a button, or one tick of
 * Run: with activities finished on the way, several commands); the controls send the commands
 * of the script language: start, advance (a step, or Run: a step every 100 ms of wall time, at a
 * speed), finish or fail a running activity (or let each finish after N ms, publishing its
 * message first), publish a message, breakpoints on states and transitions. The trace, in the
 * conformance suite's case format, saves as a case with one click.
 * <p>
 * Commands go to the session on a thread of the view's own, one at a time: an advance through a
 * busy chart takes a while, and the workbench stays responsive meanwhile. One simulation at a
 * time: a new one replaces it, and closing the view ends the simulator.
 */
public final class SimulationView extends ViewPart {

	public static final String ID = "org.kse.ui.statechart.simulationView";
	/** How often Run advances, in wall time. */
	static final int RUN_PERIOD_MS = 100;
	static final String[] SPEED_NAMES = { "0.25×", "0.5×", "1×", "2×", "5×", "10×" };
	static final double[] SPEEDS = { 0.25, 0.5, 1, 2, 5, 10 };
	static final String[] KINDS = { "State", "Signal", "Data" };

	private Display display;
	private final ExecutorService commands = Executors.newSingleThreadExecutor(runnable -> {
		Thread thread = new Thread(runnable, "KSE simulation commands");
		thread.setDaemon(true);
		return thread;
	});

	// the simulation shown
	private IFile file;
	private Model model;
	private SimulatorBuilder.Simulator simulator;
	private SimulationDriver driver;
	private MessageCatalog catalog = org.kse.messages.StandardMessages.catalog();
	/** Activities' messages published right before they finish; they outlive a restart. */
	private final Map<String, String> publishesOnFinish = new ConcurrentHashMap<>();
	/** A command is on its way: Run waits for it rather than piling commands up. */
	private boolean busy;
	private boolean running;
	/** Restart is ending the simulator and starting it anew: no command goes to either meanwhile. */
	private boolean restarting;
	/** What the diagram should show: all active states and the transitions the last commands took. */
	private List<String> drawnActive = List.of();
	private List<Integer> drawnTaken = List.of();

	// controls
	private Composite top;
	private Label hint;
	private Composite body;
	private Label clock;
	private Label message;
	private Button start;
	private Button restart;
	private Button advance;
	private Spinner stepMs;
	private Button run;
	private Combo speed;
	private Browser browser;
	private Text trace;
	private Button save;
	private Table activities;
	private Button finish;
	private Button fail;
	private Button finishAfter;
	private Spinner finishAfterMs;
	private Combo topic;
	private Combo kind;
	private Combo type;
	private Text fields;
	private Button publish;
	private Button publishOnFinish;
	private Table breakpoints;

	/** Opens the view (or brings it up) on a new simulation, replacing the one it showed. */
	public static SimulationView open(IWorkbenchPage page, IFile file, Model model, SimulatorBuilder.Simulator simulator, SimulationSession session)
			throws PartInitException {
		// the workbench's diagram server serves only models open in editors
		IDE.openEditor(page, file, StatechartEditor.ID, false);
		SimulationView view = (SimulationView) page.showView(ID, null, IWorkbenchPage.VIEW_ACTIVATE);
		view.show(file, model, simulator, session);
		// the diagram and the controls need room: the view takes the window, as a double click on its tab would
		page.setPartState(page.getReference(view), IWorkbenchPage.STATE_MAXIMIZED);
		return view;
	}

	@Override
	public void createPartControl(Composite parent) {
		display = parent.getDisplay();
		top = new Composite(parent, SWT.NONE);
		top.setLayout(new GridLayout(1, false));
		hint = new Label(top, SWT.WRAP);
		hint.setText("Select a statechart and choose KSE > Simulate: it runs here on the KSE engine, without a robot.");
	}

	/** Shows a new simulation; the last one's simulator ends. */
	public void show(IFile file, Model model, SimulatorBuilder.Simulator simulator, SimulationSession session) {
		SimulationDriver previous = driver;
		if (previous != null) {
			commands.execute(previous.session()::close);
		}
		this.file = file;
		this.model = model;
		this.simulator = simulator;
		this.driver = new SimulationDriver(session, publishesOnFinish);
		this.catalog = ModelFiles.catalog(file);
		running = false;
		busy = false;
		restarting = false;
		drawnActive = List.of();
		drawnTaken = List.of();
		setPartName("Simulation: " + model.getName());
		setContentDescription(file.getFullPath() + " on the KSE engine (" + simulator.program() + ")");
		if (body == null) {
			hint.dispose();
			createBody();
		}
		fillForModel();
		applyFinishAfter();
		if (browser != null) {
			openDiagram();
		}
		say("Ready: press Start to activate the statechart (publishes before it are allowed).", false);
		refresh(null);
		top.layout(true, true);
	}

	private void createBody() {
		body = new Composite(top, SWT.NONE);
		body.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
		GridLayout layout = new GridLayout(1, false);
		layout.marginWidth = 0;
		layout.marginHeight = 0;
		body.setLayout(layout);

		Composite bar = new Composite(body, SWT.NONE);
		bar.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
		bar.setLayout(new GridLayout(11, false));
		start = button(bar, "&Start", "Activates the statechart (UserInit, enter the root) and lets it run", this::start);
		restart = button(bar, "R&estart", "A fresh run of the same simulator: the trace starts anew; breakpoints and settings stay", this::restart);
		separator(bar);
		advance = button(bar, "&Advance", "Moves the clock on by the milliseconds beside; the engine wakes at each wake-up time on the way", this::step);
		stepMs = new Spinner(bar, SWT.BORDER);
		stepMs.setValues(100, 1, 3_600_000, 0, 10, 100);
		stepMs.setToolTipText("How far one Advance moves the clock");
		new Label(bar, SWT.NONE).setText("ms");
		separator(bar);
		run = button(bar, "&Run", "Advances every 100 ms of wall time by 100 ms times the speed, until Pause or a breakpoint", this::toggleRun);
		new Label(bar, SWT.NONE).setText("Speed:");
		speed = new Combo(bar, SWT.READ_ONLY);
		speed.setItems(SPEED_NAMES);
		speed.select(2);
		speed.setToolTipText("Simulated time per wall time while running");
		clock = new Label(bar, SWT.NONE);
		clock.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
		message = new Label(body, SWT.WRAP);
		message.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));

		SashForm across = new SashForm(body, SWT.HORIZONTAL);
		across.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
		SashForm left = new SashForm(across, SWT.VERTICAL);
		Composite diagram = new Composite(left, SWT.BORDER);
		diagram.setLayout(new org.eclipse.swt.layout.FillLayout());
		createDiagram(diagram);
		createTrace(left);
		left.setWeights(68, 32);
		Composite right = new Composite(across, SWT.NONE);
		GridLayout column = new GridLayout(1, false);
		column.marginWidth = 0;
		column.marginHeight = 0;
		right.setLayout(column);
		createActivities(right);
		createPublish(right);
		createBreakpoints(right);
		across.setWeights(62, 38);
	}

	private void createDiagram(Composite parent) {
		try {
			browser = new Browser(parent, SWT.NONE);
			browser.addProgressListener(new ProgressAdapter() {
				@Override
				public void completed(ProgressEvent event) {
					// the page draws what it is told once its diagram is shown: tell it what there is now
					drawDiagram();
				}
			});
		} catch (SWTError e) {
			browser = null;
			Label none = new Label(parent, SWT.WRAP);
			none.setText("The diagram cannot be shown: this system has no browser for SWT (" + e.getMessage() + "). The trace and the controls work.");
		}
	}

	private void createTrace(Composite parent) {
		Group group = group(parent, "Trace (a conformance case: the commands and, indented, what each caused)", 2);
		trace = new Text(group, SWT.MULTI | SWT.READ_ONLY | SWT.V_SCROLL | SWT.H_SCROLL | SWT.BORDER);
		trace.setFont(JFaceResources.getTextFont());
		trace.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true, 1, 2));
		save = button(group, "Save as &Test Case…", "Saves the statechart and this trace as a conformance case (NAME.stct and NAME.case)", this::saveCase);
		save.setLayoutData(new GridData(SWT.FILL, SWT.TOP, false, false));
	}

	private void createActivities(Composite parent) {
		Group group = group(parent, "Activities", 4);
		activities = new Table(group, SWT.BORDER | SWT.FULL_SELECTION | SWT.SINGLE);
		activities.setHeaderVisible(true);
		GridData size = new GridData(SWT.FILL, SWT.FILL, true, true, 4, 1);
		size.heightHint = 110;
		activities.setLayoutData(size);
		column(activities, "Activity", 120);
		column(activities, "Running", 110);
		column(activities, "Publishes on finish", 240);
		activities.addListener(SWT.Selection, event -> enable());
		activities.addListener(SWT.DefaultSelection, event -> end(false));
		finish = button(group, "&Finish", "The selected activity returns (sending its message first, if it has one)", () -> end(false));
		fail = button(group, "Fai&l", "The selected activity throws", () -> end(true));
		finishAfter = new Button(group, SWT.CHECK);
		finishAfter.setText("Finish each after");
		finishAfter.setToolTipText("During Advance and Run, an activity that has run this long (simulated time) is finished, by a finish command in the trace");
		finishAfter.setLayoutData(new GridData(SWT.END, SWT.CENTER, true, false));
		finishAfterMs = new Spinner(group, SWT.BORDER);
		finishAfterMs.setValues(500, 1, 3_600_000, 0, 10, 100);
		finishAfterMs.setToolTipText("Milliseconds of simulated time");
		finishAfter.addListener(SWT.Selection, event -> applyFinishAfter());
		finishAfterMs.addListener(SWT.Modify, event -> applyFinishAfter());
	}

	private void createPublish(Composite parent) {
		Group group = group(parent, "Publish a message", 4);
		new Label(group, SWT.NONE).setText("T&opic:");
		topic = new Combo(group, SWT.DROP_DOWN);
		topic.setItems(MessageCatalog.standardTopics().toArray(String[]::new));
		topic.setText(MessageCatalog.standardTopics().isEmpty() ? "" : MessageCatalog.standardTopics().get(0));
		topic.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
		new Label(group, SWT.NONE).setText("&Kind:");
		kind = new Combo(group, SWT.READ_ONLY);
		kind.setItems(KINDS);
		kind.select(0);
		new Label(group, SWT.NONE).setText("T&ype:");
		type = new Combo(group, SWT.READ_ONLY);
		type.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, 3, 1));
		new Label(group, SWT.NONE).setText("F&ields:");
		fields = new Text(group, SWT.BORDER | SWT.SINGLE);
		fields.setFont(JFaceResources.getTextFont());
		fields.setMessage("protobuf text, e.g. ballfound: 1 (Ctrl+Space proposes the fields)");
		fields.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, 3, 1));
		ContentProposalAdapter assist = new ContentProposalAdapter(fields, new TextContentAdapter(), new FieldProposals(this::chosenType), ctrlSpace(),
				new char[] { ' ', '{' });
		assist.setProposalAcceptanceStyle(ContentProposalAdapter.PROPOSAL_INSERT);
		assist.setPropagateKeys(true);
		Composite buttons = new Composite(group, SWT.NONE);
		buttons.setLayoutData(new GridData(SWT.END, SWT.CENTER, true, false, 4, 1));
		buttons.setLayout(new GridLayout(2, false));
		publishOnFinish = button(buttons, "On Finish of Selected Activity",
				"Publishes this message each time the activity selected above finishes (right before its finish command)", this::publishOnFinish);
		publish = button(buttons, "&Publish", "Publishes the message on the hub now", this::publish);
		fields.addListener(SWT.DefaultSelection, event -> publish());
	}

	private void createBreakpoints(Composite parent) {
		Group group = group(parent, "Breakpoints", 1);
		((GridData) group.getLayoutData()).grabExcessVerticalSpace = true;
		((GridData) group.getLayoutData()).verticalAlignment = SWT.FILL;
		Label explained = new Label(group, SWT.WRAP);
		explained.setText("Run, Advance and Finish stop where a ticked state is entered or a ticked transition is taken.");
		GridData wrapped = new GridData(SWT.FILL, SWT.CENTER, true, false);
		wrapped.widthHint = 200;
		explained.setLayoutData(wrapped);
		breakpoints = new Table(group, SWT.BORDER | SWT.CHECK | SWT.FULL_SELECTION | SWT.V_SCROLL);
		breakpoints.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
		breakpoints.addListener(SWT.Selection, event -> {
			if (event.detail == SWT.CHECK) {
				sendBreakpoints();
			}
		});
	}

	/** The model's states and transitions, its activities and messages. */
	private void fillForModel() {
		breakpoints.removeAll();
		Map<String, Node> nodes = new java.util.HashMap<>();
		model.getNodes().forEach(node -> collect(node, nodes));
		for (String label : driver.session().states()) {
			if (label.isBlank() || label.chars().anyMatch(Character::isWhitespace)) {
				continue; // a breakpoint names a state by its label, which has no spaces
			}
			Node node = nodes.get(label);
			TableItem item = new TableItem(breakpoints, SWT.NONE);
			String name = node == null || node.getName() == null || node.getName().equals(label) ? "" : "  " + node.getName();
			item.setText("state " + label + name);
			item.setData(label);
		}
		List<Transition> transitions = model.getTransitions();
		for (int index = 0; index < transitions.size(); index++) {
			Transition transition = transitions.get(index);
			TableItem item = new TableItem(breakpoints, SWT.NONE);
			String expression = transition.getTE() == null || transition.getTE().isBlank() ? "" : "  " + transition.getTE();
			item.setText("transition " + index + ": " + labelOf(transition.getSource()) + " -> " + labelOf(transition.getTarget()) + expression);
			item.setData(index);
		}
		activities.removeAll();
		for (String activity : new LinkedHashSet<>(driver.session().activities())) {
			TableItem item = new TableItem(activities, SWT.NONE);
			item.setText(0, activity);
			item.setData(activity);
		}
		String chosen = type.getText();
		List<String> types = catalog.messages().stream().map(MessageType::fullName).sorted().toList();
		type.setItems(types.toArray(String[]::new));
		type.select(Math.max(0, types.indexOf(chosen)));
	}

	private static void collect(Node node, Map<String, Node> nodes) {
		if (node.getLabel() != null) {
			nodes.put(node.getLabel(), node);
		}
		node.getChildren().forEach(child -> collect(child, nodes));
	}

	private static String labelOf(Node node) {
		return node == null ? "?" : node.getLabel() == null || node.getLabel().isEmpty() ? String.valueOf(node.getName()) : node.getLabel();
	}

	// ---- the commands

	/** The work of a command on the command thread: what the session answered. */
	private interface Work {
		List<Result> run(SimulationDriver driver) throws IOException, SimulationException;
	}

	/** Runs {@code work} on the command thread; the view shows what it answered. */
	private void submit(Work work) {
		SimulationDriver now = driver;
		if (now == null || busy || restarting) {
			return;
		}
		busy = true;
		enable();
		commands.execute(() -> {
			List<Result> results = List.of();
			String failure = null;
			try {
				results = work.run(now);
			} catch (IOException | SimulationException e) {
				failure = e.getMessage();
			} catch (RuntimeException e) {
				failure = e.toString();
			}
			List<Result> answered = results;
			String failed = failure;
			asyncExec(() -> {
				if (driver != now || restarting) {
					return; // a restart or a new simulation came first
				}
				busy = false;
				answered(answered, failed);
			});
		});
	}

	private void start() {
		submit(driver -> List.of(driver.execute("start")));
	}

	private void step() {
		long by = stepMs.getSelection();
		submit(driver -> driver.advance(by));
	}

	private void toggleRun() {
		running = !running;
		if (running) {
			say("Running at " + speed.getText() + "…", false);
			tick();
		} else {
			say("Paused.", false);
		}
		enable();
	}

	/** Run: one advance of 100 ms times the speed, every 100 ms of wall time, unless a command is still on its way. */
	private void tick() {
		if (!running || display.isDisposed() || body.isDisposed()) {
			return;
		}
		if (!busy) {
			long by = Math.max(1, Math.round(RUN_PERIOD_MS * SPEEDS[Math.max(0, speed.getSelectionIndex())]));
			submit(driver -> driver.advance(by));
		}
		display.timerExec(RUN_PERIOD_MS, this::tick);
	}

	private void end(boolean failIt) {
		String activity = selectedActivity();
		if (activity == null || driver.runningSince(activity).isEmpty()) {
			return;
		}
		submit(driver -> driver.end(activity, failIt));
	}

	private void applyFinishAfter() {
		if (driver != null) {
			driver.setFinishAfter(finishAfter.getSelection() ? finishAfterMs.getSelection() : 0);
		}
	}

	/** The publish command the form describes, or null (and the status says why). */
	private String publishCommand() {
		String topicName = topic.getText().strip();
		if (topicName.isEmpty() || topicName.chars().anyMatch(Character::isWhitespace)) {
			say("A topic is one word, e.g. " + String.join(", ", MessageCatalog.standardTopics()) + ".", true);
			return null;
		}
		if (type.getText().isBlank()) {
			say("Choose the message's type.", true);
			return null;
		}
		String text = fields.getText().strip().replace('\n', ' ');
		return "publish " + topicName + " " + kind.getText() + " " + type.getText() + " { " + (text.isEmpty() ? "" : text + " ") + "}";
	}

	private void publish() {
		String command = publishCommand();
		if (command != null) {
			submit(driver -> List.of(driver.execute(command)));
		}
	}

	private void publishOnFinish() {
		String activity = selectedActivity();
		String command = publishCommand();
		if (activity == null) {
			say("Select the activity (above) that publishes this message when it finishes.", true);
		} else if (command != null) {
			publishesOnFinish.put(activity, command);
			say(activity + " publishes " + command.substring("publish ".length()) + " each time it finishes (Finish, or finish after N ms).", false);
			refreshActivities();
		}
	}

	/** Tells the session which states and transitions are ticked. */
	private void sendBreakpoints() {
		List<String> states = new ArrayList<>();
		List<Integer> transitions = new ArrayList<>();
		for (TableItem item : breakpoints.getItems()) {
			if (item.getChecked()) {
				if (item.getData() instanceof String label) {
					states.add(label);
				} else if (item.getData() instanceof Integer index) {
					transitions.add(index);
				}
			}
		}
		// not traced, and allowed while a command runs: queued behind it
		SimulationDriver now = driver;
		commands.execute(() -> {
			String failure;
			try {
				Result result = now.setBreakpoints(states, transitions);
				failure = result.ok() ? null : result.error().orElse("refused");
			} catch (IOException | SimulationException e) {
				failure = e.getMessage();
			}
			String failed = failure;
			int count = states.size() + transitions.size();
			asyncExec(() -> {
				if (driver == now) {
					say(failed != null ? "The breakpoints were not set: " + failed
							: count == 0 ? "No breakpoints." : count + (count == 1 ? " breakpoint" : " breakpoints") + " set.", failed != null);
				}
			});
		});
	}

	private void restart() {
		running = false;
		SimulationDriver old = driver;
		SimulatorBuilder.Simulator program = simulator;
		restarting = true;
		busy = true;
		enable();
		say("Restarting the simulator…", false);
		commands.execute(() -> {
			old.session().close();
			SimulationSession session;
			try {
				session = SimulationSession.start(program);
			} catch (IOException | SimulationException e) {
				String failure = e.getMessage();
				asyncExec(() -> {
					if (driver == old) {
						restarting = false;
						busy = false;
						say("The simulator did not start again: " + failure, true);
						enable();
					}
				});
				return;
			}
			asyncExec(() -> {
				if (driver != old) {
					session.close();
					return;
				}
				driver = new SimulationDriver(session, publishesOnFinish);
				applyFinishAfter();
				restarting = false;
				busy = false;
				drawnActive = List.of();
				drawnTaken = List.of();
				say("Restarted: press Start.", false);
				refresh(null);
				if (breakpoints.getItems().length > 0 && java.util.Arrays.stream(breakpoints.getItems()).anyMatch(TableItem::getChecked)) {
					sendBreakpoints();
				}
			});
		});
	}

	/** What the session answered: the last result is the statechart now. */
	private void answered(List<Result> results, String failure) {
		Result last = null;
		Set<Integer> taken = new LinkedHashSet<>();
		String refused = null;
		String stopped = null;
		for (Result result : results) {
			if (!result.ok()) {
				refused = "'" + result.command() + "' was refused: " + result.error().orElse("no reason given");
				continue;
			}
			last = result;
			result.taken().forEach(segment -> taken.add(segment.transition()));
			if (result.stopped().isPresent()) {
				stopped = "Stopped at the breakpoint of " + result.stopped().get() + " (t = " + result.time() + " ms).";
			}
		}
		if (failure != null || refused != null || stopped != null) {
			running = false;
		}
		if (failure != null) {
			say(failure, true);
		} else if (refused != null) {
			say(refused, true);
		} else if (stopped != null) {
			say(stopped, false);
		} else if (last != null && !running) {
			List<String> lines = last.lines();
			say(last.command() + (lines.isEmpty() ? ": nothing happened." : ": " + String.join("; ", lines)), false);
		}
		if (last != null || !results.isEmpty()) {
			drawnTaken = List.copyOf(taken);
		}
		refresh(last);
	}

	/** The view after a command (or with {@code last} null, before any). */
	private void refresh(Result last) {
		Result now = last != null ? last : driver.session().last();
		if (now != null) {
			drawnActive = now.active();
		}
		clock.setText(now == null ? "t = 0 ms · not started"
				: "t = " + now.time() + " ms · active: " + (leaves(now.active()).isEmpty() ? "none" : String.join(", ", leaves(now.active())))
						+ (now.started() ? "" : " · not started"));
		String text = driver.session().trace().caseText(model.getName(), List.of());
		if (!text.equals(trace.getText())) {
			trace.setText(text);
			trace.setTopIndex(trace.getLineCount() - 1);
		}
		refreshActivities();
		drawDiagram();
		enable();
		clock.getParent().layout();
	}

	private void refreshActivities() {
		Result now = driver.session().last();
		long time = now == null ? 0 : now.time();
		for (TableItem item : activities.getItems()) {
			String activity = (String) item.getData();
			OptionalLong since = driver.runningSince(activity);
			item.setText(1, since.isPresent() ? "running " + (time - since.getAsLong()) + " ms" : "");
			String publishes = publishesOnFinish.get(activity);
			item.setText(2, publishes == null ? "" : publishes.substring("publish ".length()));
		}
	}

	private void drawDiagram() {
		if (browser == null || browser.isDisposed()) {
			return;
		}
		String labels = drawnActive.stream().map(SimulationView::jsString).collect(Collectors.joining(",", "[", "]"));
		String indexes = drawnTaken.stream().map(String::valueOf).collect(Collectors.joining(",", "[", "]"));
		browser.execute("window.kseSimulation && window.kseSimulation.show(" + labels + ", " + indexes + ")");
	}

	private void openDiagram() {
		try {
			browser.setUrl(WorkspaceDiagramServer.page(Path.of(file.getLocationURI())) + "&simulation=1");
		} catch (Exception e) {
			say("The diagram cannot be shown: " + e.getMessage(), true);
		}
	}

	private void enable() {
		Result now = driver.session().last();
		boolean started = now != null && now.started();
		start.setEnabled(!busy && !started);
		restart.setEnabled(!restarting);
		advance.setEnabled(!busy && !running && started);
		run.setEnabled(started);
		run.setText(running ? "&Pause" : "&Run");
		speed.setEnabled(started);
		String activity = selectedActivity();
		boolean endable = !busy && !running && activity != null && driver.runningSince(activity).isPresent();
		finish.setEnabled(endable);
		fail.setEnabled(endable);
		publish.setEnabled(!busy && !running);
		publishOnFinish.setEnabled(selectedActivity() != null);
		save.setEnabled(driver.session().trace().started() && !running);
		run.getParent().layout();
	}

	private String selectedActivity() {
		TableItem[] selected = activities.getSelection();
		return selected.length == 1 ? (String) selected[0].getData() : null;
	}

	// ---- saving the trace as a case

	private void saveCase() {
		IContainer defaultFolder = defaultCaseFolder();
		SaveCaseDialog dialog = new SaveCaseDialog(getSite().getShell(), defaultFolder.getFullPath(), freeName(defaultFolder, model.getName() + "Case"));
		if (dialog.open() != Window.OK) {
			return;
		}
		IContainer folder = dialog.container();
		String name = dialog.name();
		try {
			Path caseFile = driver.session().trace().saveCase(ModelFiles.location(folder), name, model,
					List.of("Recorded in the Simulation view of KSE on " + file.getFullPath() + " (statechart " + model.getName() + ");",
							"the lines under each command are what it must cause."));
			refreshFolder(folder);
			say("Saved the case " + folder.getFullPath().append(caseFile.getFileName().toString()) + " and its statechart " + name + ".stct.", false);
		} catch (IOException | RuntimeException e) {
			say("The case was not saved: " + e.getMessage(), true);
		}
	}

	/** The project's tests folder when it has one, else the model's folder. */
	private IContainer defaultCaseFolder() {
		IFolder tests = file.getProject().getFolder("tests");
		return tests.exists() ? tests : file.getParent();
	}

	/** {@code base1}, or the first {@code baseN} no case in the folder has. */
	static String freeName(IContainer folder, String base) {
		for (int n = 1;; n++) {
			if (!folder.getFile(org.eclipse.core.runtime.IPath.fromPortableString(base + n + ".case")).exists()) {
				return base + n;
			}
		}
	}

	private static void refreshFolder(IContainer folder) {
		try {
			// a folder made by the save: its parent learns of it
			IContainer known = folder;
			while (!known.exists() && known.getParent() != null) {
				known = known.getParent();
			}
			known.refreshLocal(IResource.DEPTH_INFINITE, null);
		} catch (CoreException e) {
			// the files are written; the workspace shows them at its next refresh
		}
	}

	// ---- small things

	private void say(String text, boolean error) {
		if (message == null || message.isDisposed()) {
			return;
		}
		message.setText(text);
		message.setForeground(error ? display.getSystemColor(SWT.COLOR_RED) : null);
		message.getParent().layout();
	}

	private void asyncExec(Runnable runnable) {
		if (!display.isDisposed()) {
			display.asyncExec(() -> {
				if (body != null && !body.isDisposed()) {
					runnable.run();
				}
			});
		}
	}

	/** The active states that have no active child (labels are paths: 0.2 holds 0.2.1). */
	static List<String> leaves(List<String> active) {
		return active.stream().filter(label -> active.stream().noneMatch(other -> other.startsWith(label + "."))).toList();
	}

	private static String jsString(String text) {
		StringBuilder quoted = new StringBuilder("\"");
		for (char c : text.toCharArray()) {
			if (c == '"' || c == '\\') {
				quoted.append('\\').append(c);
			} else if (c < 0x20 || c == 0x2028 || c == 0x2029) {
				quoted.append(String.format("\\u%04x", (int) c));
			} else {
				quoted.append(c);
			}
		}
		return quoted.append('"').toString();
	}

	private Optional<MessageType> chosenType() {
		return type == null || type.isDisposed() ? Optional.empty() : catalog.message(type.getText());
	}

	private static KeyStroke ctrlSpace() {
		try {
			return KeyStroke.getInstance("Ctrl+Space");
		} catch (ParseException e) {
			throw new IllegalStateException("Ctrl+Space is a key stroke", e);
		}
	}

	private static Group group(Composite parent, String title, int columns) {
		Group group = new Group(parent, SWT.NONE);
		group.setText(title);
		group.setLayout(new GridLayout(columns, false));
		group.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, false));
		return group;
	}

	private static Button button(Composite parent, String text, String tip, Runnable action) {
		Button button = new Button(parent, SWT.PUSH);
		button.setText(text);
		button.setToolTipText(tip);
		button.addListener(SWT.Selection, event -> action.run());
		return button;
	}

	private static void separator(Composite parent) {
		Label line = new Label(parent, SWT.SEPARATOR | SWT.VERTICAL);
		GridData size = new GridData(SWT.CENTER, SWT.FILL, false, false);
		size.heightHint = 20;
		line.setLayoutData(size);
	}

	private static void column(Table table, String title, int width) {
		TableColumn column = new TableColumn(table, SWT.NONE);
		column.setText(title);
		column.setWidth(width);
	}

	// ---- for tests and hosts

	/** The session shown now (a restart makes a new one), or null before any simulation. */
	public SimulationSession session() {
		return driver == null ? null : driver.session();
	}

	/** Whether a command is on its way to the simulator. */
	public boolean isBusy() {
		return busy;
	}

	/** Whether Run is on. */
	public boolean isRunning() {
		return running;
	}

	/** The view's controls (all of them are inside). */
	public Composite control() {
		return top;
	}

	public Browser browser() {
		return browser;
	}

	/** The status: the last command's outcome, an error (then in red), a breakpoint hit. */
	public Label message() {
		return message;
	}

	public Label clock() {
		return clock;
	}

	public Text trace() {
		return trace;
	}

	public Table activities() {
		return activities;
	}

	public Table breakpoints() {
		return breakpoints;
	}

	public Combo speed() {
		return speed;
	}

	public Spinner stepMs() {
		return stepMs;
	}

	public Button finishAfter() {
		return finishAfter;
	}

	public Spinner finishAfterMs() {
		return finishAfterMs;
	}

	public Combo topic() {
		return topic;
	}

	public Combo kind() {
		return kind;
	}

	public Combo type() {
		return type;
	}

	public Text fields() {
		return fields;
	}

	/** The proposals for the fields text with the cursor at its end (what Ctrl+Space offers). */
	public List<String> fieldProposals() {
		return java.util.Arrays.stream(new FieldProposals(this::chosenType).getProposals(fields.getText(), fields.getText().length()))
				.map(proposal -> proposal.getLabel()).sorted(Comparator.naturalOrder()).toList();
	}

	@Override
	public void dispose() {
		running = false;
		SimulationDriver last = driver;
		driver = null;
		if (last != null) {
			commands.execute(last.session()::close);
		}
		commands.shutdown();
		// closed while maximized: the editors and the other views would stay minimized
		IWorkbenchPage page = getSite().getPage();
		IWorkbenchPartReference reference = page.getReference(this);
		if (reference != null && page.getPartState(reference) == IWorkbenchPage.STATE_MAXIMIZED) {
			page.setPartState(reference, IWorkbenchPage.STATE_RESTORED);
		}
		super.dispose();
	}

	@Override
	public void setFocus() {
		(body != null ? (Control) body : top).setFocus();
	}
}
