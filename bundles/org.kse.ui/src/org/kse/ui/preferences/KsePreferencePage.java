package org.kse.ui.preferences;

import org.eclipse.core.runtime.preferences.InstanceScope;
import org.eclipse.jface.preference.FieldEditorPreferencePage;
import org.eclipse.jface.preference.RadioGroupFieldEditor;
import org.eclipse.jface.preference.StringFieldEditor;
import org.eclipse.ui.IWorkbench;
import org.eclipse.ui.IWorkbenchPreferencePage;
import org.eclipse.ui.preferences.ScopedPreferenceStore;

/** Window > Preferences > KSE: the activity editor and the code generator. */
public class KsePreferencePage extends FieldEditorPreferencePage implements IWorkbenchPreferencePage {

	public KsePreferencePage() {
		super(GRID);
		setDescription("Configure KSE: the editor of activities (BASIC states' C++) and the code generator.");
	}

	@Override
	public void init(IWorkbench workbench) {
		setPreferenceStore(new ScopedPreferenceStore(InstanceScope.INSTANCE, KsePreferences.NODE));
	}

	@Override
	protected void createFieldEditors() {
		addField(new RadioGroupFieldEditor(KsePreferences.ACTIVITY_EDITOR, "Edit activities with", 1,
				new String[][] { { "the internal text editor", KsePreferences.INTERNAL }, { "an external command", KsePreferences.EXTERNAL } },
				getFieldEditorParent(), true));
		addField(new StringFieldEditor(KsePreferences.ACTIVITY_EDITOR_COMMAND, "Activity editor command ({file}):", getFieldEditorParent()));
		addField(new RadioGroupFieldEditor(KsePreferences.GENERATOR, "Generate code with", 1,
				new String[][] { { "the built-in Monas generator", KsePreferences.INTERNAL },
						{ "an external command", KsePreferences.EXTERNAL } },
				getFieldEditorParent(), true));
		addField(new StringFieldEditor(KsePreferences.GENERATOR_COMMAND, "Generator command ({model} {folder}):", getFieldEditorParent()));
	}
}
