//! SCORM packages: an exercise as an activity a learning management system (Moodle,
//! Canvas, Blackboard, ILIAS) imports, with no server of ours. The package is a ZIP of the
//! built static site, the exercise file and its starter (never the hidden scenarios nor the
//! reference solution) and an `imsmanifest.xml` — SCORM 1.2, or SCORM 2004 4th edition —
//! whose one SCO launches the page on that exercise alone
//! (`index.html?exercise=exercise/ID.toml&scorm=1`). The page then finds the LMS's runtime
//! API and reports each Check's score (`docs/exercises.md`, "In an LMS").

use std::fmt::Write;

use super::format::{Exercise, ExerciseError};
use super::link::LinkedFile;

/// The folder of the package that holds the exercise file and its starter.
pub const SCORM_EXERCISE_DIR: &str = "exercise";

/// The list of the site's files (one path a line) that `scripts/build-web.sh` writes next
/// to `index.html`, so the page can pack itself.
pub const SITE_FILE_LIST: &str = "site-files.txt";

/// The largest `cmi.suspend_data` SCORM 1.2 allows (SCORM 2004: 64,000).
pub const SCORM_12_SUSPEND_LIMIT: usize = 4096;

/// Which SCORM the manifest declares.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ScormVersion {
    /// SCORM 1.2 (every LMS imports it).
    #[default]
    Scorm12,
    /// SCORM 2004 4th edition.
    Scorm2004,
}

/// A file of a package: its path inside it and its contents.
pub type PackageFile = (String, Vec<u8>);

/// Text for XML (attributes and content).
fn xml(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c => out.push(c),
        }
    }
    out
}

/// A path as a URL reference: every byte outside the unreserved set and `/` escaped.
fn href(path: &str) -> String {
    let mut out = String::with_capacity(path.len());
    for b in path.bytes() {
        if b.is_ascii_alphanumeric() || b"-._~/".contains(&b) {
            out.push(char::from(b));
        } else {
            let _ = write!(out, "%{b:02X}");
        }
    }
    out
}

/// An XML identifier (an NCName) made from an exercise id.
fn identifier(prefix: &str, id: &str) -> String {
    let clean: String = id
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() || "-_.".contains(c) { c } else { '_' })
        .collect();
    format!("{prefix}-{clean}")
}

/// The exercise file's path in the package.
fn exercise_path(exercise: &Exercise) -> String {
    let name: String = exercise
        .id
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() || "-_".contains(c) { c } else { '_' })
        .collect();
    format!("{SCORM_EXERCISE_DIR}/{name}.toml")
}

/// The address the LMS launches, relative to the package's root: the page on the
/// exercise, in SCORM mode.
pub fn scorm_launch(exercise: &Exercise) -> String {
    format!("index.html?exercise={}&scorm=1", href(&exercise_path(exercise)))
}

/// The `imsmanifest.xml` of a package holding `files` whose one SCO launches `exercise`.
pub fn scorm_manifest(exercise: &Exercise, files: &[&str], version: ScormVersion) -> String {
    let org = identifier("org", &exercise.id);
    let item = identifier("item", &exercise.id);
    let res = identifier("res", &exercise.id);
    let title = xml(&exercise.title);
    let launch = xml(&scorm_launch(exercise));
    let mut out = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let (scorm_type, schema_version) = match version {
        ScormVersion::Scorm12 => {
            let _ = writeln!(
                out,
                "<manifest identifier=\"{}\" version=\"1.0\"\n  \
                 xmlns=\"http://www.imsproject.org/xsd/imscp_rootv1p1p2\"\n  \
                 xmlns:adlcp=\"http://www.adlnet.org/xsd/adlcp_rootv1p2\"\n  \
                 xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\"\n  \
                 xsi:schemaLocation=\"http://www.imsproject.org/xsd/imscp_rootv1p1p2 imscp_rootv1p1p2.xsd \
                 http://www.imsglobal.org/xsd/imsmd_rootv1p2p1 imsmd_rootv1p2p1.xsd \
                 http://www.adlnet.org/xsd/adlcp_rootv1p2 adlcp_rootv1p2.xsd\">",
                identifier("plc-trainer", &exercise.id)
            );
            ("adlcp:scormtype", "1.2")
        }
        ScormVersion::Scorm2004 => {
            let _ = writeln!(
                out,
                "<manifest identifier=\"{}\" version=\"1.0\"\n  \
                 xmlns=\"http://www.imsglobal.org/xsd/imscp_v1p1\"\n  \
                 xmlns:adlcp=\"http://www.adlnet.org/xsd/adlcp_v1p3\"\n  \
                 xmlns:adlseq=\"http://www.adlnet.org/xsd/adlseq_v1p3\"\n  \
                 xmlns:adlnav=\"http://www.adlnet.org/xsd/adlnav_v1p3\"\n  \
                 xmlns:imsss=\"http://www.imsglobal.org/xsd/imsss\"\n  \
                 xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\"\n  \
                 xsi:schemaLocation=\"http://www.imsglobal.org/xsd/imscp_v1p1 imscp_v1p1.xsd \
                 http://www.adlnet.org/xsd/adlcp_v1p3 adlcp_v1p3.xsd \
                 http://www.adlnet.org/xsd/adlseq_v1p3 adlseq_v1p3.xsd \
                 http://www.adlnet.org/xsd/adlnav_v1p3 adlnav_v1p3.xsd \
                 http://www.imsglobal.org/xsd/imsss imsss_v1p0.xsd\">",
                identifier("plc-trainer", &exercise.id)
            );
            ("adlcp:scormType", "2004 4th Edition")
        }
    };
    let _ = writeln!(
        out,
        "  <metadata>\n    <schema>ADL SCORM</schema>\n    <schemaversion>{schema_version}</schemaversion>\n  </metadata>"
    );
    let _ = writeln!(
        out,
        "  <organizations default=\"{org}\">\n    <organization identifier=\"{org}\">\n      \
         <title>{title}</title>\n      <item identifier=\"{item}\" identifierref=\"{res}\" isvisible=\"true\">\n        \
         <title>{title}</title>\n      </item>\n    </organization>\n  </organizations>"
    );
    let _ = writeln!(
        out,
        "  <resources>\n    <resource identifier=\"{res}\" type=\"webcontent\" {scorm_type}=\"sco\" href=\"{launch}\">"
    );
    for f in files {
        let _ = writeln!(out, "      <file href=\"{}\"/>", xml(&href(f)));
    }
    out.push_str("    </resource>\n  </resources>\n</manifest>\n");
    out
}

/// A relative path inside a package, or why not (`..`, an absolute path, a backslash).
fn inside(path: &str) -> Result<&str, String> {
    let bad = path.is_empty()
        || path.starts_with('/')
        || path.contains('\\')
        || path.contains(':')
        || path.split('/').any(|part| part.is_empty() || part == "." || part == "..");
    if bad {
        Err(format!("“{path}” is not a file name inside the package"))
    } else {
        Ok(path)
    }
}

/// The files of the SCORM package of an exercise (in TOML or in the built form the web app
/// ships): `site` (the built static site, with its `index.html`), the exercise file and
/// every starter file it names (found by name in `starters`) under `exercise/`, and the
/// manifest.
/// Nothing else goes in: not the hidden scenarios, not the reference solution.
pub fn scorm_files(
    exercise_text: &str,
    starters: &[LinkedFile],
    site: Vec<PackageFile>,
    version: ScormVersion,
) -> Result<Vec<PackageFile>, ExerciseError> {
    let fail = |message: String| ExerciseError { message };
    let exercise = Exercise::from_text(exercise_text)?;
    let mut files: Vec<PackageFile> = Vec::new();
    for (path, bytes) in site {
        // A package made from a page that runs in an LMS: its own manifest and exercise
        // are not the site's.
        if path == "imsmanifest.xml" || path.starts_with(&format!("{SCORM_EXERCISE_DIR}/")) {
            continue;
        }
        inside(&path).map_err(|e| fail(format!("the site: {e}")))?;
        files.push((path, bytes));
    }
    if !files.iter().any(|(p, _)| p == "index.html") {
        return Err(fail(
            "the site has no index.html (build it with `bash scripts/build-web.sh`)".into(),
        ));
    }
    files.push((exercise_path(&exercise), exercise_text.as_bytes().to_vec()));
    for name in exercise.starter_files() {
        let name = inside(name).map_err(|e| fail(format!("the starter: {e}")))?;
        let Some(file) = starters.iter().find(|f| f.name == name) else {
            return Err(fail(format!(
                "the exercise names the starter {name}, which was not given"
            )));
        };
        files.push((format!("{SCORM_EXERCISE_DIR}/{name}"), file.text.as_bytes().to_vec()));
    }
    let listed: Vec<&str> = files.iter().map(|(p, _)| p.as_str()).collect();
    let manifest = scorm_manifest(&exercise, &listed, version);
    files.insert(0, ("imsmanifest.xml".to_string(), manifest.into_bytes()));
    Ok(files)
}

/// [`scorm_files`] as a ZIP archive.
pub fn scorm_package(
    exercise_text: &str,
    starters: &[LinkedFile],
    site: Vec<PackageFile>,
    version: ScormVersion,
) -> Result<Vec<u8>, ExerciseError> {
    let files = scorm_files(exercise_text, starters, site, version)?;
    crate::export::zip(&files).map_err(|e| ExerciseError { message: e.to_string() })
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    const FILE: &str = "id = \"latch\"\ntitle = \"Start & stop <latch>\"\nlevel = 1\nstarter = \"starter.st\"\nreference = \"reference.st\"\n";

    fn site() -> Vec<PackageFile> {
        vec![
            ("index.html".into(), b"<!DOCTYPE html>".to_vec()),
            ("plc-web-1a2b.wasm".into(), vec![0, 97, 115, 109]),
            ("examples/tank plant.st".into(), b"PROGRAM P END_PROGRAM".to_vec()),
            ("imsmanifest.xml".into(), b"an old one".to_vec()),
        ]
    }

    fn starter() -> LinkedFile {
        LinkedFile { name: "starter.st".into(), text: "PROGRAM Main END_PROGRAM".into() }
    }

    /// What the web app ships (the built form) packs as the TOML file does, with every
    /// starter the exercise names, each language's; a missing one is named.
    #[test]
    fn a_built_exercise_packs_every_language_starter() {
        let toml = format!(
            "{FILE}starter_ld = \"starter-ld.plcproj.json\"\nlanguages = [\"st\", \"ld\"]\n"
        );
        let built = crate::exercise::built_form(&toml, |m| m.to_string()).unwrap();
        let ld = LinkedFile { name: "starter-ld.plcproj.json".into(), text: "{}".into() };
        let files = scorm_files(&built, &[ld, starter()], site(), ScormVersion::Scorm12).unwrap();
        let paths: Vec<&str> = files.iter().map(|(p, _)| p.as_str()).collect();
        assert!(paths.contains(&"exercise/starter.st"), "{paths:?}");
        assert!(paths.contains(&"exercise/starter-ld.plcproj.json"), "{paths:?}");
        let err = scorm_files(&built, &[starter()], site(), ScormVersion::Scorm12).unwrap_err();
        assert_eq!(
            err.message,
            "the exercise names the starter starter-ld.plcproj.json, which was not given"
        );
    }

    #[test]
    fn a_package_holds_the_site_the_exercise_its_starter_and_a_scorm_12_manifest() {
        let files = scorm_files(FILE, &[starter()], site(), ScormVersion::Scorm12).unwrap();
        let paths: Vec<&str> = files.iter().map(|(p, _)| p.as_str()).collect();
        assert_eq!(
            paths,
            [
                "imsmanifest.xml",
                "index.html",
                "plc-web-1a2b.wasm",
                "examples/tank plant.st",
                "exercise/latch.toml",
                "exercise/starter.st"
            ]
        );
        let manifest = String::from_utf8(files[0].1.clone()).unwrap();
        for part in [
            "<manifest identifier=\"plc-trainer-latch\"",
            "xmlns=\"http://www.imsproject.org/xsd/imscp_rootv1p1p2\"",
            "xmlns:adlcp=\"http://www.adlnet.org/xsd/adlcp_rootv1p2\"",
            "<schema>ADL SCORM</schema>",
            "<schemaversion>1.2</schemaversion>",
            "<organizations default=\"org-latch\">",
            "<organization identifier=\"org-latch\">",
            "<title>Start &amp; stop &lt;latch&gt;</title>",
            "<item identifier=\"item-latch\" identifierref=\"res-latch\"",
            "<resource identifier=\"res-latch\" type=\"webcontent\" adlcp:scormtype=\"sco\" href=\"index.html?exercise=exercise/latch.toml&amp;scorm=1\">",
            "<file href=\"examples/tank%20plant.st\"/>",
            "<file href=\"exercise/starter.st\"/>",
        ] {
            assert!(manifest.contains(part), "{part} in\n{manifest}");
        }
        assert!(!manifest.contains("reference"));
    }

    #[test]
    fn a_scorm_2004_manifest_says_its_edition() {
        let files = scorm_files(FILE, &[starter()], site(), ScormVersion::Scorm2004).unwrap();
        let manifest = String::from_utf8(files[0].1.clone()).unwrap();
        assert!(manifest.contains("<schemaversion>2004 4th Edition</schemaversion>"));
        assert!(manifest.contains("xmlns=\"http://www.imsglobal.org/xsd/imscp_v1p1\""));
        assert!(manifest.contains("adlcp:scormType=\"sco\""));
    }

    #[test]
    fn what_cannot_be_packed_is_refused_with_the_reason() {
        let e = |r: Result<Vec<PackageFile>, ExerciseError>| r.unwrap_err().message;
        assert!(e(scorm_files(FILE, &[starter()], Vec::new(), ScormVersion::Scorm12))
            .contains("no index.html (build it with `bash scripts/build-web.sh`)"));
        assert!(e(scorm_files(FILE, &[], site(), ScormVersion::Scorm12))
            .contains("names the starter starter.st, which was not given"));
        let escaping = FILE.replace("starter.st", "../secret.st");
        assert!(e(scorm_files(&escaping, &[starter()], site(), ScormVersion::Scorm12))
            .contains("“../secret.st” is not a file name inside the package"));
        assert!(e(scorm_files("id = 1", &[], site(), ScormVersion::Scorm12)).starts_with("line 1"));
        let archive = scorm_package(FILE, &[starter()], site(), ScormVersion::Scorm12).unwrap();
        assert_eq!(&archive[..4], b"PK\x03\x04");
    }
}
