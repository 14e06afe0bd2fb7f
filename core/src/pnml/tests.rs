#![allow(clippy::unwrap_used)]

use super::*;
use crate::petri::{analyze, build, compile};
use crate::project::Project;

fn example(name: &str) -> crate::petri::PetriPou {
    let path = format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"));
    let project = Project::from_file(&std::fs::read_to_string(path).unwrap()).unwrap();
    project.petri.into_iter().next().unwrap()
}

#[test]
fn examples_round_trip_through_pnml() {
    for name in [
        "weighing-sequential.plcproj.json",
        "weighing-concurrent.plcproj.json",
        "traffic-light.plcproj.json",
    ] {
        let pou = example(name);
        let xml = export(&pou);
        assert!(is_pnml(&xml), "{name}");
        assert_eq!(import(&xml).unwrap(), pou, "{name}");
    }
}

#[test]
fn odd_text_survives_the_round_trip() {
    let mut pou = example("weighing-sequential.plcproj.json");
    pou.net.places[0].actions =
        "  s := 'a<b & \"c\"';\r\n\tx := 1; (* ]]> *)\n".replace("\r\n", "\n");
    pou.net.transitions[0].guard = "Weight > 3 AND Weight < 9".into();
    pou.net.arcs[0].weight = 3;
    assert_eq!(import(&export(&pou)).unwrap(), pou);
}

/// A net as another tool writes it: two pages, a reference place, no tool data.
const FOREIGN: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<!-- written by some editor -->
<pnml xmlns="http://www.pnml.org/version-2009/grammar/pnml">
  <net id="net-1" type="http://www.pnml.org/version-2009/grammar/ptnet">
    <name><text>2 lights</text></name>
    <page id="top">
      <place id="p1"><name><text>P1</text></name><initialMarking><text>1</text></initialMarking></place>
      <transition id="t1"><name><text>go</text></name></transition>
      <arc id="a1" source="p1" target="t1"/>
      <arc id="a2" source="t1" target="ref20"/>
      <referencePlace id="ref20" ref="p20"/>
      <page id="sub">
        <place id="p20"><name><text>P20</text></name>
          <graphics><position x="10.5" y="-3"/></graphics></place>
        <transition id="t2"/>
        <arc id="a3" source="p20" target="t2"><inscription><text>1</text></inscription></arc>
        <arc id="a4" source="t2" target="p1"/>
      </page>
    </page>
  </net>
</pnml>
"#;

#[test]
fn a_foreign_net_imports_with_labels_from_the_place_names() {
    let pou = import(FOREIGN).unwrap();
    assert_eq!(pou.name, "Net_2_lights");
    let labels: Vec<(&str, i64, u32)> =
        pou.net.places.iter().map(|p| (p.id.as_str(), p.label, p.tokens)).collect();
    assert_eq!(labels, vec![("p1", 1, 1), ("p20", 20, 0)]);
    assert_eq!(pou.net.places[1].position.unwrap().x, 10.5);
    assert_eq!(pou.net.arcs.len(), 4);
    assert_eq!((pou.net.arcs[1].from.as_str(), pou.net.arcs[1].to.as_str()), ("t1", "p20"));
    assert!(pou.net.transitions.iter().all(|t| t.guard.is_empty()));
    let net = build(&pou.net).unwrap();
    let a = analyze(&net, 100);
    assert_eq!((a.states, a.safe, a.live), (2, Some(true), Some(true)));
    // It generates and runs: both guards are TRUE, so the token moves every scan.
    let st = compile(&pou).unwrap().generated.st;
    assert!(st.contains("CASE p OF") && st.contains("20: (* P20 *)"), "{st}");
}

#[test]
fn labels_fall_back_to_document_order_when_names_repeat_numbers() {
    let xml = FOREIGN.replace("<text>P20</text>", "<text>Q1</text>");
    let pou = import(&xml).unwrap();
    let labels: Vec<i64> = pou.net.places.iter().map(|p| p.label).collect();
    assert_eq!(labels, vec![1, 2]);
}

fn error(xml: &str) -> PnmlError {
    import(xml).unwrap_err()
}

#[test]
fn bad_files_give_located_errors() {
    let e = error("<pnml><net id=\"n\"><page id=\"p\"><place id=\"a\"></page></net></pnml>");
    assert!(e.message.starts_with("malformed XML"), "{e}");
    let e = error("<?xml version=\"1.0\"?>\n<project/>");
    assert_eq!((e.line, e.column), (2, 1));
    assert!(e.message.contains("root element is <project>"), "{e}");
    let e = error("<pnml>\n  <net id=\"n\">\n    <page id=\"p\">\n      <place id=\"a\"><initialMarking><text>two</text></initialMarking></place>\n");
    assert!(e.message.contains("never closed"), "{e}");
    let xml = "<pnml>\n  <net id=\"n\">\n    <page id=\"p\">\n      <place id=\"a\"><initialMarking><text>two</text></initialMarking></place>\n    </page>\n  </net>\n</pnml>";
    let e = error(xml);
    assert_eq!((e.line, e.column), (4, 7));
    assert!(e.message.contains("`two` is not a whole number"), "{e}");
    let e = error("<pnml><net id=\"n\"><page id=\"p\">\n<place/></page></net></pnml>");
    assert_eq!((e.line, e.column), (2, 1));
    assert!(e.message.contains("no id"), "{e}");
    let e = error("<pnml><net id=\"n\"><page id=\"p\"><place id=\"a\"/>\n  <arc id=\"x\" source=\"a\" target=\"b\"/></page></net></pnml>");
    assert_eq!((e.line, e.column), (2, 3));
    assert!(e.message.contains("`b`"), "{e}");
    let e = error("<pnml><net id=\"n\" type=\"http://www.pnml.org/version-2009/grammar/symmetricnet\"/></pnml>");
    assert!(e.message.contains("only place/transition nets"), "{e}");
    let e = error("<pnml><net id=\"n\"><page id=\"p\"><place id=\"a\"/><transition id=\"t\"/><arc id=\"x\" source=\"a\" target=\"t\"><inscription><text>0</text></inscription></arc></page></net></pnml>");
    assert!(e.message.contains("at least 1"), "{e}");
    assert!(e.to_string().ends_with("[E0516]"));
}

#[test]
fn an_error_is_data_and_reads_in_polish_and_czech_with_its_program_text() {
    use crate::i18n::Lang;
    let xml = "<pnml><net id=\"n\"><page id=\"p\"><place id=\"a\"/>\n  <arc id=\"x\" source=\"a\" target=\"b\"/></page></net></pnml>";
    let e = error(xml);
    let english = "line 2, column 3: the arc refers to `b`, which is not a place or transition of the net [E0516]";
    assert_eq!(e.to_string(), english);
    assert_eq!(e.said().english, english);
    assert_eq!(e.said.english, e.message);
    assert_eq!(e.said().message.render(Lang::En), english);
    let polish = e.said().message.render(Lang::Pl);
    assert_eq!(
        polish,
        "wiersz 2, kolumna 3: łuk wskazuje na `b`, który nie jest miejscem ani przejściem tej sieci [E0516]"
    );
    assert_eq!(
        e.said().message.render(Lang::Cs),
        "řádek 2, sloupec 3: hrana odkazuje na `b`, což není místo ani přechod této sítě [E0516]"
    );

    // The phrase naming the number is translated, the text read stays as written.
    let xml = "<pnml><net id=\"n\"><page id=\"p\">\n<place id=\"a\"><initialMarking><text> two </text></initialMarking></place></page></net></pnml>";
    let e = error(xml);
    assert_eq!(
        e.to_string(),
        "line 2, column 1: the initial marking `two` is not a whole number [E0516]"
    );
    assert_eq!(
        e.said.message.render(Lang::Pl),
        "znakowanie początkowe `two` nie jest liczbą całkowitą"
    );
    assert_eq!(e.said.message.render(Lang::Cs), "počáteční značení `two` není celé číslo");

    // Every error's English is its display, whatever made it.
    for xml in [
        "<pnml><net id=\"n\"><page id=\"p\"><place id=\"a\"></page></net></pnml>",
        "<?xml version=\"1.0\"?>\n<project/>",
        "<pnml>\n<net id=\"n\">",
        "<pnml><net id=\"n\"><toolspecific tool=\"plc-trainer\"><emergency/></toolspecific></net></pnml>",
        "<pnml><net id=\"n\"><toolspecific tool=\"plc-trainer\"><macroPlace id=\"m\"><place/></macroPlace></toolspecific></net></pnml>",
        "<pnml><net id=\"n\"><toolspecific tool=\"plc-trainer\"><options sync=\"odd\"/></toolspecific></net></pnml>",
        "<pnml a=\"1\" a=\"2\"/>",
        "<pnml a=\"&bogus;\"/>",
        "<pnml><net id=\"n\">&bogus;</net></pnml>",
        "<pnml/><pnml/>",
        "",
    ] {
        let e = error(xml);
        assert_eq!(e.said().english, e.to_string());
        assert_eq!(e.said().message.render(Lang::En), e.to_string());
        assert_ne!(e.said().message.render(Lang::Pl), e.to_string(), "{e}");
    }
}

#[test]
fn pnml_is_recognised_by_its_root() {
    assert!(is_pnml(FOREIGN));
    assert!(is_pnml("<pnml/>"));
    assert!(!is_pnml(
        "<?xml version=\"1.0\"?><project xmlns=\"http://www.plcopen.org/xml/tc6_0201\"/>"
    ));
    assert!(!is_pnml("PROGRAM P END_PROGRAM"));
}
