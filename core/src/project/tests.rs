#![allow(clippy::unwrap_used)]

use super::*;

#[test]
fn a_project_file_round_trips() {
    let mut p = Project::new("Latch");
    p.settings.traced = vec!["Motor".into()];
    assert_eq!(Project::from_file(&p.to_file()).unwrap(), p);
}

#[test]
fn bad_files_give_clear_errors() {
    assert!(matches!(Project::from_file("not json"), Err(ProjectError::NotJson(_))));
    assert_eq!(Project::from_file("{}"), Err(ProjectError::NotAProject));
    assert_eq!(Project::from_file(r#"{"schema": 99}"#), Err(ProjectError::TooNew(99)));
    assert!(matches!(
        Project::from_file(r#"{"schema": 1, "name": 3}"#),
        Err(ProjectError::Invalid(_))
    ));
    // Settings may be missing (older files).
    let p = Project::from_file(r#"{"schema": 1, "name": "a", "source": "x"}"#).unwrap();
    assert_eq!(p.settings.cycle_ms, 10);
}

#[test]
fn errors_are_data_whose_english_is_their_display() {
    use crate::i18n::Lang;
    let errors = [
        Project::from_file("not json").unwrap_err(),
        Project::from_file("{}").unwrap_err(),
        Project::from_file(r#"{"schema": 99}"#).unwrap_err(),
        Project::from_file(r#"{"schema": 1, "name": 3}"#).unwrap_err(),
        Project::from_file(
            r#"{"schema": 1, "name": "a", "source": "x", "settings": {"cycle_ms": 0}}"#,
        )
        .unwrap_err(),
    ];
    for e in &errors {
        assert_eq!(e.said().english, e.to_string());
        assert_eq!(e.said().message.render(Lang::En), e.to_string());
        assert_ne!(e.said().message.render(Lang::Pl), e.to_string());
        assert_ne!(e.said().message.render(Lang::Cs), e.to_string());
    }
    assert_eq!(
        errors[2].said().message.render(Lang::Pl),
        "ten projekt został zapisany przez nowszą wersję trenażera (wersja formatu 99); zaktualizuj stronę"
    );
    // serde_json's own words stay as they are; the field and the cycle check are ours.
    assert_eq!(
        errors[3].said().message.render(Lang::Cs),
        "soubor projektu je poškozený: invalid type: integer `3`, expected a string at line 1 column 23"
    );
    assert_eq!(
        errors[4].to_string(),
        "the project file is damaged: settings.cycle_ms: a scan cycle is 1 to 60000 ms, not 0 ms"
    );
    assert_eq!(
        errors[4].said().message.render(Lang::Pl),
        "plik projektu jest uszkodzony: settings.cycle_ms: cykl programu trwa od 1 do 60000 ms, a nie 0 ms"
    );

    let shares = [
        ShareError::NotAShareLink,
        ShareError::BadEncoding,
        ShareError::BadCompression,
        ShareError::BadProject(ProjectError::NotAProject),
    ];
    for e in &shares {
        assert_eq!(e.said().english, e.to_string());
        assert_ne!(e.said().message.render(Lang::Pl), e.to_string());
    }
    assert_eq!(
        shares[3].said().message.render(Lang::Pl),
        "ten link do udostępnienia nie zawiera poprawnego projektu: ten plik JSON nie jest projektem trenażera PLC"
    );
}

#[test]
fn share_links_round_trip_and_reject_damage() {
    let p = Project::new("Shared latch");
    let link = encode_share(&p);
    assert!(link.starts_with("p="));
    assert!(link.chars().all(|c| c.is_ascii_alphanumeric() || "=-_".contains(c)));
    assert_eq!(decode_share(&format!("#{link}")).unwrap(), p);
    assert_eq!(decode_share("#x=abc"), Err(ShareError::NotAShareLink));
    assert_eq!(decode_share("#p=***"), Err(ShareError::BadEncoding));
    let truncated = &link[..link.len() / 2];
    assert!(decode_share(truncated).is_err());
    let not_a_project = format!("p={}", {
        use base64::Engine;
        base64::engine::general_purpose::URL_SAFE_NO_PAD
            .encode(miniz_oxide::deflate::compress_to_vec(b"[1,2]", 6))
    });
    assert!(matches!(decode_share(&not_a_project), Err(ShareError::BadProject(_))));
}

#[test]
fn the_chosen_program_is_kept_and_old_settings_still_load() {
    let old = r#"{"schema":1,"name":"p","source":"","settings":{"cycle_ms":20,"traced":[],"breakpoints":[]}}"#;
    let p = Project::from_file(old).unwrap();
    assert_eq!((p.settings.cycle_ms, p.settings.program.as_deref()), (20, None));
    assert!(!p.to_file().contains("\"program\""), "no field written while unset");
    let mut chosen = p.clone();
    chosen.settings.program = Some("PartCounter".into());
    let back = Project::from_file(&chosen.to_file()).unwrap();
    assert_eq!(back.settings.program.as_deref(), Some("PartCounter"));
}

#[test]
fn a_cycle_time_out_of_range_is_refused_with_its_field() {
    // Issue 11: a cycle_ms that overflowed the nanosecond clock or became 1 ns silently.
    for bad in ["0", "18446744073709551615", "60001"] {
        let text = format!(
            r#"{{"schema":1,"name":"p","source":"","settings":{{"cycle_ms":{bad},"traced":[],"breakpoints":[]}}}}"#
        );
        let e = Project::from_file(&text).unwrap_err();
        assert!(e.to_string().contains("settings.cycle_ms"), "{e}");
        assert!(e.to_string().contains("1 to 60000 ms"), "{e}");
    }
}

#[test]
fn project_files_are_indented_exactly_as_serde_json_pretty_prints() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples");
    let mut seen = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.to_string_lossy().ends_with(".plcproj.json") {
            let p = Project::from_file(&std::fs::read_to_string(&path).unwrap()).unwrap();
            assert_eq!(p.to_file(), serde_json::to_string_pretty(&p).unwrap(), "{path:?}");
            seen += 1;
        }
    }
    assert!(seen >= 4);
    let mut odd = Project::new("quote \" brace { [ ] } colon : comma , \\ end");
    odd.source = "x := '\"';\n(* {a: [1, 2]} *)".into();
    assert_eq!(odd.to_file(), serde_json::to_string_pretty(&odd).unwrap());
}

/// The first screen's reader (no diagram models' readers) reads a project without
/// diagram POUs as `from_file` does, says so for one with them, and never calls a file
/// damaged that `from_file` reads.
#[test]
fn a_project_read_without_the_diagram_readers_is_the_same_or_asks_for_them() {
    let with_scene = include_str!("../../../examples/tank-plant.plcproj.json");
    let mut traced = Project::new("Latch");
    traced.settings.traced = vec!["Motor".into()];
    traced.settings.program = Some("Main".into());
    for text in [with_scene.to_string(), traced.to_file()] {
        let full = Project::from_file(&text).unwrap();
        assert_eq!(Project::from_file_without_diagrams(&text), Ok(full));
    }
    let bad = [
        "not json",
        "{}",
        r#"{"schema": 99}"#,
        r#"{"schema": 1, "name": 3}"#,
        r#"{"schema": 1, "name": "a", "source": "x", "settings": {"cycle_ms": 0}}"#,
        r#"{"schema": 1, "name": "a", "source": "x", "ladder": 5}"#,
    ];
    for text in bad {
        assert_eq!(Project::from_file_without_diagrams(text), Project::from_file(text), "{text}");
    }
    for text in [
        include_str!("../../../examples/latch-ladder.plcproj.json"),
        include_str!("../../../examples/weighing-plant.plcproj.json"),
    ] {
        assert!(Project::from_file(text).is_ok());
        assert_eq!(
            Project::from_file_without_diagrams(text),
            Err(ProjectError::NeedsDiagramReaders)
        );
    }
    // A network POU is not looked at: whether it is sound is for `from_file` to say.
    let network = r#"{"schema": 1, "name": "a", "source": "", "networks": [{}]}"#;
    assert!(matches!(Project::from_file(network), Err(ProjectError::Invalid(_))));
    assert_eq!(
        Project::from_file_without_diagrams(network),
        Err(ProjectError::NeedsDiagramReaders)
    );
    assert_eq!(
        Project::name_in_file(with_scene).as_deref(),
        Some("Tank with level switches (ST plant)")
    );
    assert_eq!(Project::name_in_file("{}"), None);
}
