//! A JUnit XML report checked against the schema CI tools read (Jenkins' `junit-10.xsd`,
//! which GitLab CI and CodeGrade follow): the elements, where each may stand, their
//! attributes, the required ones, and the counts a suite declares. Shared by the test
//! binaries that read `grade --format junit` and a class run's `junit.xml`.

use roxmltree::{Document, Node};

/// An element of the schema: its attributes (required first, then optional) and the
/// elements it may hold.
struct Element {
    name: &'static str,
    required: &'static [&'static str],
    optional: &'static [&'static str],
    children: &'static [&'static str],
}

const SCHEMA: &[Element] = &[
    Element {
        name: "testsuites",
        required: &[],
        optional: &["name", "time", "tests", "failures", "disabled", "errors"],
        children: &["testsuite"],
    },
    Element {
        name: "testsuite",
        required: &["name", "tests"],
        optional: &[
            "failures",
            "errors",
            "time",
            "disabled",
            "skipped",
            "timestamp",
            "hostname",
            "id",
            "package",
            "file",
            "log",
            "url",
            "version",
        ],
        children: &["properties", "testcase", "system-out", "system-err"],
    },
    Element {
        name: "properties",
        required: &[],
        optional: &[],
        children: &["property"],
    },
    Element {
        name: "property",
        required: &["name", "value"],
        optional: &[],
        children: &[],
    },
    Element {
        name: "testcase",
        required: &["name"],
        optional: &["classname", "assertions", "time", "status", "file", "line"],
        children: &["skipped", "error", "failure", "system-out", "system-err"],
    },
    Element {
        name: "skipped",
        required: &[],
        optional: &["message"],
        children: &[],
    },
    Element {
        name: "failure",
        required: &[],
        optional: &["message", "type"],
        children: &[],
    },
    Element {
        name: "error",
        required: &[],
        optional: &["message", "type"],
        children: &[],
    },
    Element {
        name: "system-out",
        required: &[],
        optional: &[],
        children: &[],
    },
    Element {
        name: "system-err",
        required: &[],
        optional: &[],
        children: &[],
    },
];

/// The number in attribute `name` of `node`, 0 when absent.
fn count(node: Node, name: &str) -> usize {
    node.attribute(name).map_or(0, |v| {
        v.parse()
            .unwrap_or_else(|_| panic!("{name}=\"{v}\" is not a count"))
    })
}

fn check(node: Node) {
    let name = node.tag_name().name();
    let element = SCHEMA
        .iter()
        .find(|e| e.name == name)
        .unwrap_or_else(|| panic!("<{name}> is not a JUnit element"));
    for required in element.required {
        assert!(
            node.attribute(*required).is_some(),
            "<{name}> lacks {required}"
        );
    }
    for attribute in node.attributes() {
        let a = attribute.name();
        assert!(
            element.required.contains(&a) || element.optional.contains(&a),
            "<{name}> has no attribute {a}"
        );
    }
    for child in node.children().filter(Node::is_element) {
        let c = child.tag_name().name();
        assert!(element.children.contains(&c), "<{name}> may not hold <{c}>");
        check(child);
    }
    if name == "testsuite" {
        let cases: Vec<Node> = node
            .children()
            .filter(|c| c.has_tag_name("testcase"))
            .collect();
        let with = |kind: &str| {
            cases
                .iter()
                .filter(|c| c.children().any(|k| k.has_tag_name(kind)))
                .count()
        };
        assert_eq!(count(node, "tests"), cases.len(), "tests= of a suite");
        assert_eq!(
            count(node, "failures"),
            with("failure"),
            "failures= of a suite"
        );
        assert_eq!(count(node, "errors"), with("error"), "errors= of a suite");
        assert_eq!(
            count(node, "skipped"),
            with("skipped"),
            "skipped= of a suite"
        );
    }
}

/// Checks `xml` against the schema, and the totals of `<testsuites>` against its suites;
/// returns the parsed document's `(tests, failures, skipped)` totals.
pub fn validate(xml: &str) -> (usize, usize, usize) {
    let doc = Document::parse(xml).unwrap_or_else(|e| panic!("not XML: {e}\n{xml}"));
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "testsuites", "{xml}");
    check(root);
    let suites: Vec<Node> = root.children().filter(Node::is_element).collect();
    let sum = |a: &str| suites.iter().map(|s| count(*s, a)).sum::<usize>();
    assert_eq!(count(root, "tests"), sum("tests"), "tests= of testsuites");
    assert_eq!(
        count(root, "failures"),
        sum("failures"),
        "failures= of testsuites"
    );
    assert_eq!(
        count(root, "errors"),
        sum("errors"),
        "errors= of testsuites"
    );
    (sum("tests"), sum("failures"), sum("skipped"))
}
