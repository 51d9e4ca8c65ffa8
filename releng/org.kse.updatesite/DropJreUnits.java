import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;
import java.util.zip.ZipOutputStream;

/**
 * Takes the JRE units ({@code a.jre.*}) that Tycho copies into an assembled repository out of
 * its metadata. On an update site they are harmful: p2 could install "Java 25" into an IDE that
 * runs on Java 21 to satisfy a bundle's execution environment. The IDE's own profile provides
 * its JRE. The XZ copy of the metadata is dropped (the JDK cannot write XZ): p2 reads content.jar.
 *
 * <p>Run with {@code java DropJreUnits.java <repository folder>} after the repository is assembled.
 */
public final class DropJreUnits {

	private static final Pattern JRE_UNIT = Pattern.compile("\\s*<unit id='(?:config\\.)?a\\.jre[^']*'.*?</unit>", Pattern.DOTALL);
	private static final Pattern UNITS_SIZE = Pattern.compile("<units size='(\\d+)'>");

	public static void main(String[] arguments) throws IOException {
		Path repository = Path.of(arguments[0]);
		Path jar = repository.resolve("content.jar");
		String content;
		try (ZipFile zip = new ZipFile(jar.toFile())) {
			content = new String(zip.getInputStream(zip.getEntry("content.xml")).readAllBytes(), StandardCharsets.UTF_8);
		}
		Matcher units = JRE_UNIT.matcher(content);
		int dropped = 0;
		StringBuilder kept = new StringBuilder();
		while (units.find()) {
			units.appendReplacement(kept, "");
			dropped++;
		}
		units.appendTail(kept);
		Matcher size = UNITS_SIZE.matcher(kept);
		if (!size.find()) {
			throw new IOException(jar + ": no <units size='…'> in content.xml");
		}
		String fixed = kept.replace(size.start(1), size.end(1), Integer.toString(Integer.parseInt(size.group(1)) - dropped)).toString();

		Path written = Files.createTempFile(repository, "content", ".jar");
		try (OutputStream file = Files.newOutputStream(written); ZipOutputStream zip = new ZipOutputStream(file)) {
			zip.putNextEntry(new ZipEntry("content.xml"));
			zip.write(fixed.getBytes(StandardCharsets.UTF_8));
			zip.closeEntry();
		}
		Files.move(written, jar, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
		Files.deleteIfExists(repository.resolve("content.xml.xz"));
		Path index = repository.resolve("p2.index");
		Files.writeString(index, Files.readString(index).replace("metadata.repository.factory.order=content.xml.xz,content.xml,", "metadata.repository.factory.order=content.xml,"));
		System.out.println("DropJreUnits: " + dropped + " JRE unit(s) taken out of " + repository);
	}
}
