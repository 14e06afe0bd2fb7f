#![allow(clippy::unwrap_used)]

use super::*;

fn store() -> ProjectStore<MemoryBackend> {
    ProjectStore::new(MemoryBackend::default())
}

fn named(name: &str) -> Project {
    Project::new(name)
}

#[test]
fn the_store_lists_adds_renames_duplicates_and_deletes() {
    let mut store = store();
    let (a, _) = store.add(&named("A"), 1000).unwrap();
    let (b, _) = store.add(&named("B"), 2000).unwrap();
    assert_ne!(a, b);
    let names: Vec<String> = store.list().unwrap().into_iter().map(|p| p.name).collect();
    assert_eq!(names, ["B", "A"]);
    store.rename(&a, "A2", 3000).unwrap();
    assert_eq!(store.load(&a).unwrap().name, "A2");
    let c = store.duplicate(&a, 4000).unwrap();
    assert_eq!(store.load(&c).unwrap().name, "A2 (copy)");
    store.delete(&b).unwrap();
    assert!(matches!(store.load(&b), Err(StoreError::NotFound(_))));
    assert_eq!(store.list().unwrap().len(), 2);
    assert!(!store.backend().entries().keys().any(|k| k.contains(&b)), "its text is gone too");
}

#[test]
fn a_save_writes_a_new_revision_and_removes_the_old_one_last() {
    let mut store = store();
    let (a, rev) = store.add(&named("A"), 1).unwrap();
    assert_eq!(rev, 1);
    let rev2 = store.save(&a, &named("A, edited"), Some(rev), 2).unwrap();
    assert_eq!(rev2, 2);
    let keys: Vec<&String> = store.backend().entries().keys().collect();
    assert_eq!(keys, ["plc-trainer/v1/index", &format!("plc-trainer/v1/project/{a}@2")]);
    assert_eq!(store.open(&a).unwrap(), Opened { project: named("A, edited"), rev: 2 });
}

#[test]
fn adding_never_overwrites_and_a_full_quota_loses_nothing() {
    let mut store = ProjectStore::new(MemoryBackend::with_quota(1500));
    let (a, rev) = store.add(&named("A"), 5).unwrap();
    let (b, _) = store.add(&named("B"), 5).unwrap();
    assert_ne!(a, b, "same clock, still a new id");
    let before = store.backend().entries().clone();
    let mut big = named("Big");
    big.source = "x".repeat(5000);
    assert_eq!(store.save(&a, &big, Some(rev), 6), Err(StoreError::QuotaExceeded));
    assert_eq!(store.add(&big, 6), Err(StoreError::QuotaExceeded));
    assert_eq!(store.backend().entries(), &before, "storage exactly as it was");
    assert_eq!(store.load(&a).unwrap().name, "A", "the old version is still there");
}

#[test]
fn a_failed_index_write_takes_back_the_new_revision() {
    let mut store = store();
    let (a, rev) = store.add(&named("A"), 1).unwrap();
    let before = store.backend().entries().clone();
    // Room for the new revision's text, but not for the longer index it needs.
    let renamed = named("A with a much longer name than before");
    let new_text = format!("plc-trainer/v1/project/{a}@2").len() + renamed.to_file().len();
    store.backend.set_quota(Some(store.backend().used() + new_text));
    let result = store.save(&a, &renamed, Some(rev), 2);
    assert_eq!(result, Err(StoreError::QuotaExceeded));
    assert_eq!(store.backend().entries(), &before);
}

#[test]
fn a_project_changed_in_another_tab_is_not_overwritten() {
    let mut store = store();
    let (a, rev) = store.add(&named("A"), 1).unwrap();
    // The other tab saves first.
    let theirs = store.save(&a, &named("theirs"), Some(rev), 2).unwrap();
    assert_eq!(
        store.save(&a, &named("mine"), Some(rev), 3),
        Err(StoreError::Conflict { id: a.clone(), stored: Some(theirs) })
    );
    assert_eq!(store.load(&a).unwrap().name, "theirs");
    // Choosing to keep mine: save over the revision now stored.
    store.save(&a, &named("mine"), Some(theirs), 4).unwrap();
    assert_eq!(store.load(&a).unwrap().name, "mine");
    // Deleted in the other tab: saving is refused, not silently re-created.
    store.delete(&a).unwrap();
    assert_eq!(
        store.save(&a, &named("mine"), Some(theirs + 1), 5),
        Err(StoreError::Conflict { id: a.clone(), stored: None })
    );
}

#[test]
fn a_damaged_index_is_rebuilt_from_the_projects_and_kept() {
    let mut store = store();
    let (a, _) = store.add(&named("A"), 0x10).unwrap();
    let (b, rev_b) = store.add(&named("B"), 0x20).unwrap();
    store.backend.set("plc-trainer/v1/index", "{\"layout\": 2, \"proj").unwrap();
    let list = store.list().unwrap();
    let names: Vec<&str> = list.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names, ["B", "A"], "ordered by the time in their ids");
    let message = store.index_damage().unwrap().unwrap();
    assert!(message.contains("rebuilt from the 2 projects"), "{message}");
    let said = store.index_damage_said().unwrap().unwrap();
    assert_eq!(said.english, message);
    assert_eq!(
        said.message.render(crate::i18n::Lang::Pl),
        "Lista projektów w tej przeglądarce była uszkodzona. Odtworzono ją z projektów znalezionych w pamięci (liczba: 2); uszkodzona lista jest zachowana pod kluczem „plc-trainer/v1/index.damaged”."
    );
    // Saving writes a sound index, keeping the damaged one first.
    store.save(&b, &named("B2"), Some(rev_b), 0x30).unwrap();
    assert_eq!(
        store.backend().get("plc-trainer/v1/index.damaged").unwrap().as_deref(),
        Some("{\"layout\": 2, \"proj")
    );
    assert_eq!(store.index_damage().unwrap(), None);
    assert_eq!(store.load(&a).unwrap().name, "A");
    assert_eq!(store.load(&b).unwrap().name, "B2");
}

#[test]
fn a_damaged_index_is_not_replaced_when_its_copy_cannot_be_kept() {
    let mut store = store();
    let (a, rev) = store.add(&named("A"), 1).unwrap();
    store.backend.set("plc-trainer/v1/index", "not json").unwrap();
    // Room for the new revision's text, not for the copy of the damaged index.
    let new_text = format!("plc-trainer/v1/project/{a}@2").len() + named("A2").to_file().len();
    store.backend.set_quota(Some(store.backend().used() + new_text));
    let before = store.backend().entries().clone();
    assert_eq!(store.save(&a, &named("A2"), Some(rev), 2), Err(StoreError::QuotaExceeded));
    assert_eq!(store.backend().entries(), &before);
}

#[test]
fn a_damaged_project_is_listed_readable_and_deletable_but_never_opened() {
    let mut store = store();
    let (a, _) = store.add(&named("A"), 1).unwrap();
    let (b, rev_b) = store.add(&named("B"), 2).unwrap();
    let key = format!("plc-trainer/v1/project/{b}@{rev_b}");
    store.backend.set(&key, "{\"schema\": 1, \"name\": ").unwrap();
    assert!(matches!(store.open(&b), Err(StoreError::Damaged(_))));
    let damaged = store.damaged().unwrap();
    assert_eq!(damaged.len(), 1);
    assert_eq!(damaged[0].0, b);
    let said = store.damaged_said().unwrap();
    assert_eq!(said[0].1.english, damaged[0].1);
    assert!(
        said[0].1.message.render(crate::i18n::Lang::Cs).starts_with(
            "uložený projekt je poškozený: toto není soubor projektu (není to JSON: EOF while parsing"
        ),
        "{:?}",
        said[0].1
    );
    assert_eq!(store.raw(&b).unwrap(), "{\"schema\": 1, \"name\": ");
    assert!(store.rename(&b, "x", 3).is_err(), "not rewritten by a rename");
    assert_eq!(store.raw(&b).unwrap(), "{\"schema\": 1, \"name\": ");
    assert_eq!(store.load(&a).unwrap().name, "A", "the others open");
    store.delete(&b).unwrap();
    assert!(store.damaged().unwrap().is_empty());
    assert!(store.backend().get(&key).unwrap().is_none());
}

#[test]
fn a_listed_project_whose_text_is_missing_is_damaged() {
    let mut store = store();
    let (a, rev) = store.add(&named("A"), 1).unwrap();
    store.backend.remove(&format!("plc-trainer/v1/project/{a}@{rev}")).unwrap();
    let e = store.open(&a).unwrap_err();
    assert!(e.to_string().contains("missing from storage"), "{e}");
    assert_eq!(
        e.said().message.render(crate::i18n::Lang::Pl),
        format!("zapisany projekt jest uszkodzony: plik projektu jest uszkodzony: lista go wymienia, ale jego tekstu brak w pamięci (klucz plc-trainer/v1/project/{a}@{rev})")
    );
    assert_eq!(store.damaged().unwrap().len(), 1);
    store.delete(&a).unwrap();
    assert!(store.list().unwrap().is_empty());
}

/// Storage as the first release (layout 1) left it.
fn layout_1() -> MemoryBackend {
    let mut b = MemoryBackend::default();
    let index = r#"[{"id":"p10","name":"Old A","modified_ms":16},{"id":"p20","name":"Old B","modified_ms":32}]"#;
    b.set("plc-trainer/v1/index", index).unwrap();
    b.set("plc-trainer/v1/project/p10", &named("Old A").to_file()).unwrap();
    b.set("plc-trainer/v1/project/p20", &named("Old B").to_file()).unwrap();
    b
}

#[test]
fn storage_layout_1_is_read_and_migrated_project_by_project() {
    let mut store = ProjectStore::new(layout_1());
    let names: Vec<String> = store.list().unwrap().into_iter().map(|p| p.name).collect();
    assert_eq!(names, ["Old B", "Old A"]);
    assert_eq!(store.index_damage().unwrap(), None);
    let opened = store.open("p10").unwrap();
    assert_eq!((opened.project.name.as_str(), opened.rev), ("Old A", 0));
    store.save("p10", &named("New A"), Some(0), 48).unwrap();
    let keys: Vec<&str> = store.backend().entries().keys().map(String::as_str).collect();
    assert_eq!(
        keys,
        ["plc-trainer/v1/index", "plc-trainer/v1/project/p10@1", "plc-trainer/v1/project/p20"]
    );
    let index = store.backend().get("plc-trainer/v1/index").unwrap().unwrap();
    assert!(index.starts_with("{\"layout\":2,"), "{index}");
    assert_eq!(store.load("p10").unwrap().name, "New A");
    assert_eq!(store.load("p20").unwrap().name, "Old B", "not yet migrated, still there");
    let (c, _) = store.add(&named("C"), 64).unwrap();
    assert_eq!(store.list().unwrap().len(), 3);
    assert_eq!(store.load(&c).unwrap().name, "C");
}

#[test]
fn storage_written_by_a_newer_trainer_is_listed_but_not_written() {
    let mut b = MemoryBackend::default();
    let index = r#"{"layout":3,"projects":[{"id":"p1","name":"Future","modified_ms":1,"rev":4,"colour":"red"}]}"#;
    b.set("plc-trainer/v1/index", index).unwrap();
    b.set("plc-trainer/v1/project/p1@4", &named("Future").to_file()).unwrap();
    let mut store = ProjectStore::new(b);
    let before = store.backend().entries().clone();
    assert_eq!(store.list().unwrap()[0].name, "Future");
    assert!(store.index_damage().unwrap().unwrap().contains("newer trainer"));
    assert_eq!(store.save("p1", &named("x"), Some(4), 2), Err(StoreError::TooNew(3)));
    assert_eq!(store.add(&named("y"), 2), Err(StoreError::TooNew(3)));
    assert_eq!(store.backend().entries(), &before);
}

#[test]
fn store_errors_are_data_whose_english_is_their_display() {
    use crate::i18n::Lang;
    let errors = [
        StoreError::QuotaExceeded,
        StoreError::Unavailable("local storage is disabled".into()),
        StoreError::NotFound("p12".into()),
        StoreError::Damaged(ProjectError::NotAProject),
        StoreError::Conflict { id: "p1".into(), stored: Some(2) },
        StoreError::Conflict { id: "p1".into(), stored: None },
        StoreError::TooNew(3),
    ];
    for e in &errors {
        assert_eq!(e.said().english, e.to_string());
        assert_eq!(e.said().message.render(Lang::En), e.to_string());
        assert_ne!(e.said().message.render(Lang::Pl), e.to_string());
        assert_ne!(e.said().message.render(Lang::Cs), e.to_string());
    }
    assert_eq!(errors[2].said().message.render(Lang::Pl), "brak projektu `p12`");
    assert_eq!(
        errors[6].said().message.render(Lang::Cs),
        "projekty v tomto prohlížeči uložil novější trenažér (uspořádání úložiště 3); načtěte stránku znovu, aby se aktualizovala"
    );
}

#[test]
fn a_new_id_is_never_one_whose_text_is_still_in_storage() {
    let mut store = store();
    store.backend.set("plc-trainer/v1/project/p5@3", "orphan").unwrap();
    let (id, _) = store.add(&named("A"), 5).unwrap();
    assert_eq!(id, "p6");
    assert_eq!(
        store.backend().get("plc-trainer/v1/project/p5@3").unwrap().as_deref(),
        Some("orphan")
    );
}

#[test]
fn an_opening_that_never_finished_is_remembered() {
    let mut store = store();
    assert_eq!(store.interrupted_opening().unwrap(), None);
    store.mark_opening("p1").unwrap();
    assert_eq!(store.interrupted_opening().unwrap().as_deref(), Some("p1"));
    store.clear_opening().unwrap();
    assert_eq!(store.interrupted_opening().unwrap(), None);
    assert!(ProjectStore::<MemoryBackend>::is_store_key("plc-trainer/v1/index"));
    assert!(!ProjectStore::<MemoryBackend>::is_store_key("other"));
}

/// A store that reads without the diagram models' readers (the web app's first screen)
/// opens a project with diagram POUs as "needs the readers", never lists it as damaged,
/// and a store with them opens it; a project without diagram POUs opens either way.
#[test]
fn a_store_without_the_diagram_readers_neither_opens_nor_damages_a_ladder_project() {
    let mut full = store();
    let ladder =
        Project::from_file(include_str!("../../../../examples/latch-ladder.plcproj.json")).unwrap();
    let (with, _) = full.add(&ladder, 1).unwrap();
    let (without, _) = full.add(&named("Plain"), 2).unwrap();
    let light =
        ProjectStore::with_reader(full.backend().clone(), Project::from_file_without_diagrams);
    assert_eq!(light.open(&with), Err(StoreError::Damaged(ProjectError::NeedsDiagramReaders)));
    assert_eq!(light.damaged().unwrap(), Vec::<(String, String)>::new());
    assert_eq!(light.load(&without).unwrap(), named("Plain"));
    assert_eq!(full.load(&with).unwrap(), ladder);
    let names: Vec<String> = light.list().unwrap().into_iter().map(|p| p.name).collect();
    assert_eq!(names, ["Plain", ladder.name.as_str()]);
}
