package org.kse.ui.messages;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.jface.viewers.ColumnLabelProvider;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.jface.viewers.TreeViewer;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.ui.views.contentoutline.ContentOutlinePage;
import org.kse.ui.text.OutlineContent;
import org.kse.messages.EnumType;
import org.kse.messages.Field;
import org.kse.messages.MessageType;
import org.kse.messages.ProtoFile;

/**
 * The Outline of a {@code .proto} file: its messages (nested ones inside), enums with their
 * values, and fields as {@code name = number : type}, in file order; a click selects the name.
 */
class ProtoOutline extends ContentOutlinePage {

	enum Kind {
		MESSAGE, ENUM, FIELD, VALUE
	}

	/** One entry; {@code offset} and {@code length} are those of the name in the text. */
	record Entry(Kind kind, String label, int offset, int length, List<Entry> children) {
	}

	private final ProtoEditor editor;

	ProtoOutline(ProtoEditor editor) {
		this.editor = editor;
	}

	@Override
	public void createControl(Composite parent) {
		super.createControl(parent);
		TreeViewer viewer = getTreeViewer();
		viewer.setContentProvider(new OutlineContent(entry -> ((Entry) entry).children()));
		viewer.setLabelProvider(new ColumnLabelProvider() {
			@Override
			public String getText(Object element) {
				return ((Entry) element).label();
			}

			@Override
			public Color getForeground(Object element) {
				return switch (((Entry) element).kind()) {
				case MESSAGE -> ProtoScanner.MESSAGE;
				case ENUM -> ProtoScanner.ENUM;
				case FIELD -> null;
				case VALUE -> ProtoScanner.NUMBER;
				};
			}
		});
		viewer.setAutoExpandLevel(TreeViewer.ALL_LEVELS);
		viewer.addSelectionChangedListener(event -> {
			if (event.getSelection() instanceof IStructuredSelection selection && selection.getFirstElement() instanceof Entry entry) {
				editor.selectAndReveal(entry.offset(), entry.length());
			}
		});
		update(null);
	}

	/** Shows the declarations of the text just checked (null: reads the editor's text now). */
	void update(ProtoFile checked) {
		TreeViewer viewer = getTreeViewer();
		if (viewer == null || viewer.getControl().isDisposed()) {
			return;
		}
		String text = editor.getText();
		ProtoFile file = checked != null ? checked : editor.parse(text);
		viewer.setInput(entries(file, new LinkedProto.Positions(text), text));
	}

	/** The outline of a parsed file whose text is {@code text}. */
	static List<Entry> entries(ProtoFile file, LinkedProto.Positions positions, String text) {
		List<Entry> entries = new ArrayList<>();
		file.messages().forEach(message -> entries.add(message(message, positions, text)));
		file.enums().forEach(enumType -> entries.add(enumType(enumType, positions, text)));
		return sorted(entries);
	}

	private static Entry message(MessageType message, LinkedProto.Positions positions, String text) {
		List<Entry> children = new ArrayList<>();
		for (Field field : message.fields()) {
			String type = field.mapKeyTypeName().map(key -> "map<" + key + ", " + field.typeName() + ">").orElse(field.typeName());
			children.add(new Entry(Kind.FIELD, field.name() + " = " + field.number() + " : " + type,
					positions.offset(field.line(), field.column()), field.name().length(), List.of()));
		}
		message.nestedMessages().forEach(nested -> children.add(message(nested, positions, text)));
		message.nestedEnums().forEach(nested -> children.add(enumType(nested, positions, text)));
		return new Entry(Kind.MESSAGE, message.name(), positions.offset(message.line(), message.column()), message.name().length(),
				sorted(children));
	}

	private static Entry enumType(EnumType enumType, LinkedProto.Positions positions, String text) {
		int at = positions.offset(enumType.line(), enumType.column());
		List<Entry> values = new ArrayList<>();
		int from = at;
		for (Map.Entry<String, Integer> value : enumType.values().entrySet()) {
			// The model keeps no positions of values: the first "NAME =" after the previous one is it.
			Matcher name = Pattern.compile("\\b" + Pattern.quote(value.getKey()) + "\\s*=").matcher(text);
			int offset = name.find(from) ? name.start() : at;
			from = Math.max(from, offset);
			values.add(new Entry(Kind.VALUE, value.getKey() + " = " + value.getValue(), offset,
					offset == at ? enumType.name().length() : value.getKey().length(), List.of()));
		}
		return new Entry(Kind.ENUM, enumType.name(), at, enumType.name().length(), values);
	}

	/** File order: the model keeps fields, nested messages and enums apart. */
	private static List<Entry> sorted(List<Entry> entries) {
		return entries.stream().sorted(Comparator.comparingInt(Entry::offset)).toList();
	}
}
