package org.kse.ui.messages.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IFolder;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.ITextOperationTarget;
import org.eclipse.jface.text.ITextSelection;
import org.eclipse.jface.text.ITextViewer;
import org.eclipse.jface.text.Region;
import org.eclipse.jface.text.hyperlink.IHyperlink;
import org.eclipse.jface.text.source.ISourceViewer;
import org.eclipse.jface.viewers.StructuredSelection;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.StyleRange;
import org.eclipse.swt.graphics.RGB;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Tree;
import org.eclipse.swt.widgets.TreeItem;
import org.eclipse.ui.IPageLayout;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IDE;
import org.eclipse.ui.keys.IBindingService;
import org.eclipse.ui.views.contentoutline.ContentOutline;
import org.eclipse.ui.views.contentoutline.ContentOutlinePage;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer.OrderAnnotation;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.extension.ExtendWith;
import org.kse.testing.ui.Ui;
import org.kse.testing.ui.UnexpectedDialogs;
import org.kse.ui.messages.ProtoEditor;
import org.kse.ui.messages.ProtoHyperlinks;

/**
 * A team's message files in the workbench, as a user meets them: a project with two .proto files,
 * one importing the other and a standard message; problems marked while typing and gone when
 * fixed, also those that come from the other file; F3 and Ctrl+click to a type's declaration,
 * in the other file or in a standard file opened read-only; the Outline. Screenshots land in
 * target/screenshots.
 */
@ExtendWith(UnexpectedDialogs.class)
@TestMethodOrder(OrderAnnotation.class)
class MessageEditorTest {

	private static final String MARKER = "org.kse.ui.messages.messageProblem";

	private static final String COMMON = """
			// Shared by the team's messages.
			syntax = "proto2";

			message Position {
			  optional float x = 1;
			  optional float y = 2;
			}

			enum Side {
			  LEFT = 0;
			  RIGHT = 1;
			}
			""";

	private static final String TEAM = """
			/* What a player tells the team,
			   once a second. */
			syntax = "proto2";

			import "Common.proto";
			import "kse/messages/WorldInfo.proto";

			message TeamMessage {
			  optional Position where = 1;
			  optional Side side = 2;
			  repeated int32 seen_ids = 3;
			  optional WorldInfo world = 4;
			  message Plan {
			    optional string role = 1 [default = "goalie // keeper"];
			  }
			  optional Plan plan = 5;
			}
			""";

	private static IFile common;
	private static IFile team;
	private static ProtoEditor editor;

	@BeforeAll
	static void createProject() throws CoreException {
		IProject project = ResourcesPlugin.getWorkspace().getRoot().getProject("Team");
		if (!project.exists()) {
			project.create(null);
		}
		project.open(null);
		IFolder messages = project.getFolder("messages");
		if (!messages.exists()) {
			messages.create(true, true, null);
		}
		common = messages.getFile("Common.proto");
		team = messages.getFile("Team.proto");
		common.create(new ByteArrayInputStream(COMMON.getBytes(StandardCharsets.UTF_8)), true, null);
		team.create(new ByteArrayInputStream(TEAM.getBytes(StandardCharsets.UTF_8)), true, null);
		PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell().setSize(1280, 800);
	}

	@AfterAll
	static void closeEditors() {
		Ui.page().closeAllEditors(false);
	}

	private static List<IMarker> problems(IFile file, int severity) {
		try {
			List<IMarker> found = new ArrayList<>();
			for (IMarker marker : file.findMarkers(MARKER, false, IResource.DEPTH_ZERO)) {
				if (marker.getAttribute(IMarker.SEVERITY, -1) == severity) {
					found.add(marker);
				}
			}
			found.sort(java.util.Comparator.comparingInt(marker -> marker.getAttribute(IMarker.CHAR_START, 0)));
			return found;
		} catch (CoreException e) {
			throw new AssertionError(e);
		}
	}

	private static List<IMarker> errors() {
		return problems(team, IMarker.SEVERITY_ERROR);
	}

	private static List<String> messages(List<IMarker> markers) {
		return markers.stream().map(marker -> marker.getAttribute(IMarker.MESSAGE, "")).toList();
	}

	private static IDocument document(ProtoEditor part) {
		return part.getDocumentProvider().getDocument(part.getEditorInput());
	}

	private static ISourceViewer viewer(ProtoEditor part) {
		return (ISourceViewer) part.getAdapter(ITextOperationTarget.class);
	}

	private static String selected(ProtoEditor part) {
		return ((ITextSelection) part.getSelectionProvider().getSelection()).getText();
	}

	/** Replaces the first {@code old} after {@code from} in the editor, as typing would. */
	private static int type(String from, String old, String replacement) throws Exception {
		IDocument document = document(editor);
		int at = document.get().indexOf(old, document.get().indexOf(from));
		assertTrue(at >= 0, () -> old + " in the text");
		document.replace(at, old.length(), replacement);
		return at;
	}

	private static boolean noErrors() {
		return errors().isEmpty();
	}

	@Test
	@Order(1)
	void aProtoFileOpensInTheMessageEditorColouredAndWithoutProblems() throws Exception {
		assertEquals(ProtoEditor.ID, IDE.getDefaultEditor(team).getId(), "the message editor is the default for .proto files");
		editor = assertInstanceOf(ProtoEditor.class, IDE.openEditor(Ui.page(), team));
		assertTrue(Ui.waitUntil(() -> editor.lastCheckNanos() > 0, 10_000), "the file is checked as it opens");
		System.out.printf("message editor: the check on opening took %.1f ms%n", editor.lastCheckNanos() / 1e6);
		assertEquals(List.of(), messages(errors()), "the two files and the standard WorldInfo are correct");

		String text = document(editor).get();
		var widget = viewer(editor).getTextWidget();
		StyleRange keyword = widget.getStyleRangeAtOffset(text.indexOf("message TeamMessage"));
		assertEquals(new RGB(0x7f, 0x00, 0x55), keyword.foreground.getRGB(), "'message' is a keyword");
		assertEquals(SWT.BOLD, keyword.fontStyle & SWT.BOLD);
		StyleRange scalar = widget.getStyleRangeAtOffset(text.indexOf("int32"));
		assertEquals(new RGB(0x1f, 0x4e, 0x9c), scalar.foreground.getRGB(), "int32 is a scalar type");
		StyleRange comment = widget.getStyleRangeAtOffset(text.indexOf("once a second"));
		assertEquals(new RGB(0x3f, 0x7f, 0x5f), comment.foreground.getRGB(), "the second line of a /* */ comment");
		StyleRange string = widget.getStyleRangeAtOffset(text.indexOf("// keeper"));
		assertEquals(new RGB(0x2a, 0x00, 0xff), string.foreground.getRGB(), "// inside a string is part of the string");
		StyleRange number = widget.getStyleRangeAtOffset(text.indexOf("= 5;") + 2);
		assertEquals(new RGB(0xb7, 0x1c, 0x1c), number.foreground.getRGB(), "a field number");
		StyleRange name = widget.getStyleRangeAtOffset(text.indexOf("TeamMessage"));
		assertTrue(name == null || name.foreground == null || !name.foreground.getRGB().equals(new RGB(0x7f, 0x00, 0x55)),
				"a message's name is no keyword");
	}

	@Test
	@Order(2)
	void aFileWithAProblemShowsItAsItOpensAndItStaysOnThatFile() throws Exception {
		IFile scratch = team.getParent().getFile(new org.eclipse.core.runtime.Path("Scratch.proto"));
		scratch.create(new ByteArrayInputStream("syntax = \"proto2\";\nmessage Scratch {\n  optional Ball ball = 1;\n  optional Nothing n = 2;\n}\n"
				.getBytes(StandardCharsets.UTF_8)), true, null);
		ProtoEditor opened = assertInstanceOf(ProtoEditor.class, IDE.openEditor(Ui.page(), scratch));
		// Ball is a standard message, used without importing its file: protoc refuses that too
		List<String> expected = List.of("type Ball is defined in WorldInfo.proto, which Scratch.proto does not import",
				"unknown type Nothing of field n in message Scratch");
		// the check on opening and the folder's catalog check may each mark the file; wait for both
		Ui.waitUntil(() -> messages(problems(scratch, IMarker.SEVERITY_ERROR)).equals(expected), 10_000);
		assertEquals(expected, messages(problems(scratch, IMarker.SEVERITY_ERROR)), "marked without typing");
		assertEquals(4, problems(scratch, IMarker.SEVERITY_ERROR).get(1).getAttribute(IMarker.LINE_NUMBER, 0));
		Ui.settle(300);
		assertEquals(List.of(), messages(errors()), "Scratch.proto's problems are not Team.proto's");
		Ui.page().closeEditor(opened, false);
		scratch.delete(true, null);
		Ui.page().activate(editor);
	}

	@Test
	@Order(3)
	void aMissingSemicolonIsMarkedWhileTypingAndGoesWhenFixed() throws Exception {
		long start = System.currentTimeMillis();
		int at = type("optional Side", "= 2;", "= 2");
		assertTrue(Ui.waitUntil(() -> !noErrors(), 10_000), "an error marker for the missing ';'");
		long shown = System.currentTimeMillis() - start;
		IMarker marker = errors().get(0);
		int line = document(editor).getLineOfOffset(at) + 1;
		assertEquals(line, marker.getAttribute(IMarker.LINE_NUMBER, 0), "on the line typed");
		String message = marker.getAttribute(IMarker.MESSAGE, "");
		assertTrue(message.startsWith("expected ';' after field side"), () -> "a readable message: " + message);
		assertEquals(at + "= ".length(), marker.getAttribute(IMarker.CHAR_START, -1), "the squiggle is under the 2 the ';' should follow");
		assertEquals(at + "= 2".length(), marker.getAttribute(IMarker.CHAR_END, -1));
		assertTrue(editor.isDirty(), "while typing, unsaved");
		Ui.settle(100); // the check notes its time once its markers are made
		System.out.printf("message editor: marker shown %d ms after typing (250 ms pause included); the check took %.1f ms%n",
				shown, editor.lastCheckNanos() / 1e6);
		Ui.screenshot("01-missing-semicolon");

		type("optional Side", "= 2", "= 2;");
		assertTrue(Ui.waitUntil(MessageEditorTest::noErrors, 10_000), () -> "the marker goes once fixed: " + messages(errors()));
	}

	@Test
	@Order(4)
	void anUnknownTypeIsMarkedAtItsNameWithItsName() throws Exception {
		int at = type("optional Position", "Position", "Positon");
		assertTrue(Ui.waitUntil(() -> !noErrors(), 10_000), "an error marker for the unknown type");
		assertEquals(List.of("unknown type Positon of field where in message TeamMessage"), messages(errors()));
		IMarker marker = errors().get(0);
		assertEquals(at, marker.getAttribute(IMarker.CHAR_START, -1), "the squiggle starts at the type name");
		assertEquals(at + "Positon".length(), marker.getAttribute(IMarker.CHAR_END, -1), "and covers it whole");
		assertEquals(document(editor).getLineOfOffset(at) + 1, marker.getAttribute(IMarker.LINE_NUMBER, 0));
		Ui.screenshot("02-unknown-type");

		type("optional Positon", "Positon", "Position");
		assertTrue(Ui.waitUntil(MessageEditorTest::noErrors, 10_000), () -> "the marker goes once fixed: " + messages(errors()));
		editor.doSave(null);
	}

	@Test
	@Order(5)
	void theOtherFilesProblemsStayThereButItsTypesCountHere() throws Exception {
		// Common.proto loses Side and gets a syntax error of its own, on disk (not in an editor)
		String broken = COMMON.replace("optional float y = 2;", "optional float y = 2").replaceAll("(?s)enum Side \\{.*?\\}\n", "");
		common.setContents(new ByteArrayInputStream(broken.getBytes(StandardCharsets.UTF_8)), IResource.FORCE, null);
		assertTrue(Ui.waitUntil(() -> !noErrors(), 10_000), "Team.proto is checked again when Common.proto changes");
		assertEquals(List.of("unknown type Side of field side in message TeamMessage"), messages(errors()),
				"Team.proto shows its own problem only, not the missing ';' of Common.proto");

		common.setContents(new ByteArrayInputStream(COMMON.getBytes(StandardCharsets.UTF_8)), IResource.FORCE, null);
		assertTrue(Ui.waitUntil(MessageEditorTest::noErrors, 10_000), () -> "fixed with Common.proto: " + messages(errors()));
	}

	@Test
	@Order(6)
	void f3OnATypeOfTheOtherFileOpensItWithTheNameSelected() throws Exception {
		Ui.page().activate(editor);
		IBindingService bindings = PlatformUI.getWorkbench().getService(IBindingService.class);
		List<String> keys = Arrays.stream(bindings.getActiveBindingsFor("org.kse.ui.messages.openDeclaration"))
				.map(Object::toString).toList();
		assertTrue(keys.contains("F3"), () -> "F3 opens the declaration in the message editor: " + keys);

		String text = document(editor).get();
		editor.selectAndReveal(text.indexOf("Position where") + 3, 0);
		Ui.run("org.kse.ui.messages.openDeclaration");
		ProtoEditor opened = assertInstanceOf(ProtoEditor.class, Ui.page().getActiveEditor());
		assertEquals(common, opened.getFile(), "Common.proto opens");
		assertEquals("Position", selected(opened), "with the name of the message selected");
		assertEquals(COMMON.indexOf("Position"), ((ITextSelection) opened.getSelectionProvider().getSelection()).getOffset());

		// a nested type of the same file: the cursor moves to its declaration in place
		Ui.page().activate(editor);
		editor.selectAndReveal(text.indexOf("Plan plan"), 0);
		Ui.run("org.kse.ui.messages.openDeclaration");
		assertEquals(editor, Ui.page().getActiveEditor());
		assertEquals(text.indexOf("Plan {"), ((ITextSelection) editor.getSelectionProvider().getSelection()).getOffset());

		// a scalar has no declaration: the status line says so, nothing opens
		editor.selectAndReveal(text.indexOf("int32"), 0);
		Ui.run("org.kse.ui.messages.openDeclaration");
		assertEquals(editor, Ui.page().getActiveEditor());
		assertEquals("int32 is a scalar type of protobuf", editor.statusMessage());
	}

	@Test
	@Order(7)
	void ctrlClickOnAStandardTypeOpensTheStandardFileReadOnly() throws Exception {
		Ui.page().activate(editor);
		String text = document(editor).get();
		int at = text.indexOf("WorldInfo world");
		ITextViewer viewer = viewer(editor);
		IHyperlink[] links = new ProtoHyperlinks(editor).detectHyperlinks(viewer, new Region(at + 2, 0), false);
		assertNotNull(links, "WorldInfo is a link under Ctrl");
		assertEquals(new Region(at, "WorldInfo".length()), links[0].getHyperlinkRegion());
		assertEquals(null, new ProtoHyperlinks(editor).detectHyperlinks(viewer, new Region(text.indexOf("world ="), 0), false),
				"a field's name is no link");
		links[0].open();
		ProtoEditor standard = assertInstanceOf(ProtoEditor.class, Ui.page().getActiveEditor());
		assertEquals("WorldInfo.proto", standard.getEditorInput().getName());
		assertEquals(null, standard.getFile(), "the bundled file, not a workspace file");
		assertFalse(standard.isEditable(), "a standard file is read-only");
		assertEquals("WorldInfo", selected(standard));
		assertTrue(document(standard).get().contains("message WorldInfo {"));
		assertTrue(standard.statusMessage().contains("kse/messages/WorldInfo.proto"), standard::statusMessage);

		// and from the standard file on, to the standard type of a field there
		String world = document(standard).get();
		standard.selectAndReveal(world.indexOf("RobotPose", world.indexOf("message WorldInfo")), 0);
		Ui.run("org.kse.ui.messages.openDeclaration");
		assertEquals("RobotPose", selected(standard));
		assertEquals(world.indexOf("message RobotPose") + "message ".length(),
				((ITextSelection) standard.getSelectionProvider().getSelection()).getOffset());
		Ui.page().closeEditor(standard, false);
		Ui.page().closeAllEditors(false);
		editor = (ProtoEditor) IDE.openEditor(Ui.page(), team);
	}

	@Test
	@Order(8)
	void theOutlineListsTheMessagesAndSelectsANameInTheText() throws Exception {
		ContentOutline view = (ContentOutline) Ui.page().showView(IPageLayout.ID_OUTLINE);
		Ui.page().activate(editor);
		Ui.settle(800);
		Tree tree = (Tree) ((ContentOutlinePage) view.getCurrentPage()).getControl();
		assertEquals(List.of("TeamMessage"), Arrays.stream(tree.getItems()).map(TreeItem::getText).toList());
		TreeItem message = tree.getItems()[0];
		assertEquals(List.of("where = 1 : Position", "side = 2 : Side", "seen_ids = 3 : int32", "world = 4 : WorldInfo", "Plan",
				"plan = 5 : Plan"), Arrays.stream(message.getItems()).map(TreeItem::getText).toList());
		assertEquals(List.of("role = 1 : string"), Arrays.stream(message.getItems()[4].getItems()).map(TreeItem::getText).toList());

		((ContentOutlinePage) view.getCurrentPage()).setSelection(new StructuredSelection(message.getItems()[1].getData()));
		String text = document(editor).get();
		assertEquals("side", selected(editor), "the field's name is selected");
		assertEquals(text.indexOf("side = 2"), ((ITextSelection) editor.getSelectionProvider().getSelection()).getOffset());

		// the outline follows the text
		type("message Plan", "message Plan {", "enum Mode { ATTACK = 0; DEFEND = 1; }\n  message Plan {");
		assertTrue(Ui.waitUntil(() -> tree.getItems()[0].getItems().length == 7, 10_000), "the new enum is shown");
		TreeItem mode = tree.getItems()[0].getItems()[4];
		assertEquals("Mode", mode.getText());
		assertEquals(List.of("ATTACK = 0", "DEFEND = 1"), Arrays.stream(mode.getItems()).map(TreeItem::getText).toList());
		((ContentOutlinePage) view.getCurrentPage()).setSelection(new StructuredSelection(mode.getItems()[1].getData()));
		assertEquals("DEFEND", selected(editor));
	}

	@Test
	@Order(9)
	void theEditorWithAMarkerAndItsOutline() throws Exception {
		type("optional Side", "Side side", "Sides side");
		assertTrue(Ui.waitUntil(() -> !noErrors(), 10_000));
		assertEquals(List.of("unknown type Sides of field side in message TeamMessage"), messages(errors()));
		var problemsView = Ui.page().showView(IPageLayout.ID_PROBLEM_VIEW);
		Ui.settle(1000);
		for (Tree tree : Ui.find(problemsView.getSite().getShell(), Tree.class)) {
			for (TreeItem item : tree.getItems()) {
				if (item.getText().startsWith("Errors")) {
					// as a click on the arrow: the view fills its groups when told they expand
					Event expand = new Event();
					expand.item = item;
					tree.notifyListeners(SWT.Expand, expand);
					item.setExpanded(true);
				}
			}
		}
		Ui.page().activate(editor);
		Ui.settle(500);
		Ui.screenshot("03-editor-marker-outline");
	}
}
