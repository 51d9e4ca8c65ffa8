package org.kse.ui.text;

import java.util.List;
import java.util.function.Function;

import org.eclipse.jface.viewers.ITreeContentProvider;

/** The content of an Outline whose input is the list of its top entries and whose entries know their children. */
public final class OutlineContent implements ITreeContentProvider {

	private final Function<Object, List<?>> children;

	public OutlineContent(Function<Object, List<?>> children) {
		this.children = children;
	}

	@Override
	public Object[] getElements(Object input) {
		return ((List<?>) input).toArray();
	}

	@Override
	public Object[] getChildren(Object element) {
		return children.apply(element).toArray();
	}

	@Override
	public Object getParent(Object element) {
		return null;
	}

	@Override
	public boolean hasChildren(Object element) {
		return !children.apply(element).isEmpty();
	}
}
