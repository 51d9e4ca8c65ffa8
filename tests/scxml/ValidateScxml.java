import java.io.File;
import java.util.List;

import javax.xml.XMLConstants;
import javax.xml.transform.stream.StreamSource;
import javax.xml.validation.SchemaFactory;
import javax.xml.validation.Validator;

import org.xml.sax.SAXParseException;

/**
 * Checks SCXML documents against the W3C SCXML schema: {@code java ValidateScxml.java <scxml.xsd> <doc>...}.
 * Prints each invalid document with line:column and why; exit 1 when one is invalid. (run.sh's
 * check; the JUnit tests of org.kse.scxml check the same way.)
 */
public class ValidateScxml {
	public static void main(String[] args) throws Exception {
		SchemaFactory factory = SchemaFactory.newInstance(XMLConstants.W3C_XML_SCHEMA_NS_URI);
		factory.setProperty(XMLConstants.ACCESS_EXTERNAL_DTD, "");
		factory.setProperty(XMLConstants.ACCESS_EXTERNAL_SCHEMA, "file");
		Validator validator = factory.newSchema(new File(args[0])).newValidator();
		int invalid = 0;
		for (String document : List.of(args).subList(1, args.length)) {
			try {
				validator.validate(new StreamSource(new File(document)));
			} catch (SAXParseException e) {
				System.out.println(document + ":" + e.getLineNumber() + ":" + e.getColumnNumber() + ": " + e.getMessage());
				invalid++;
			}
		}
		System.out.println((args.length - 1 - invalid) + " of " + (args.length - 1) + " documents are valid SCXML");
		System.exit(invalid == 0 ? 0 : 1);
	}
}
