package org.kse.ui.messages;

import java.io.ByteArrayInputStream;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;

import org.eclipse.core.resources.IEncodedStorage;
import org.eclipse.core.resources.IStorage;
import org.eclipse.core.runtime.IPath;
import org.eclipse.core.runtime.PlatformObject;
import org.eclipse.jface.resource.ImageDescriptor;
import org.eclipse.ui.IPersistableElement;
import org.eclipse.ui.IStorageEditorInput;
import org.kse.messages.StandardMessages;

/**
 * A standard message file, as bundled with KSE: no workspace file, so it opens read-only (a user
 * replaces a standard message by defining it again in the project's messages folder).
 */
final class StandardFileInput extends PlatformObject implements IStorageEditorInput {

	private final String name;

	StandardFileInput(String name) {
		this.name = name;
	}

	/** The path the catalog names the file by, and the user's files import it by. */
	String importPath() {
		return StandardMessages.FOLDER + name;
	}

	String fileName() {
		return name;
	}

	@Override
	public IStorage getStorage() {
		return new Storage();
	}

	@Override
	public boolean exists() {
		return true;
	}

	@Override
	public ImageDescriptor getImageDescriptor() {
		return ImageDescriptor.getMissingImageDescriptor();
	}

	@Override
	public String getName() {
		return name;
	}

	@Override
	public IPersistableElement getPersistable() {
		return null; // rebuilt from the bundle, never restored from a closed workbench
	}

	@Override
	public String getToolTipText() {
		return importPath() + ", a standard message file of KSE (read-only)";
	}

	@Override
	public boolean equals(Object other) {
		return other instanceof StandardFileInput input && input.name.equals(name);
	}

	@Override
	public int hashCode() {
		return name.hashCode();
	}

	private final class Storage extends PlatformObject implements IEncodedStorage {
		@Override
		public InputStream getContents() {
			return new ByteArrayInputStream(StandardMessages.text(name).getBytes(StandardCharsets.UTF_8));
		}

		@Override
		public String getCharset() {
			return StandardCharsets.UTF_8.name();
		}

		@Override
		public IPath getFullPath() {
			return IPath.fromPortableString(importPath());
		}

		@Override
		public String getName() {
			return name;
		}

		@Override
		public boolean isReadOnly() {
			return true;
		}
	}
}
