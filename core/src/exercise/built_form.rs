//! The built form of an exercise file: what the web app ships its exercises as, so that
//! opening one needs neither a TOML reader nor a Markdown renderer (`docs/loading.md`). It
//! is JSON: `{"plc_exercise":1,"statement_html":"…","exercise":{…}}`, where `exercise`
//! holds the file's keys and values as they are (TOML tables become objects) except the
//! statement, which is given rendered (and each translation's, `lang.pl.statement` given as
//! `lang.pl.statement_html`). [`crate::exercise::Exercise::from_built`] reads it
//! with the same checks as a TOML file.
//!
//! This file uses nothing of the crate but `toml` and `serde_json`: the web app's build
//! script includes it to write the shipped exercises in this form.

/// How an exercise text in the built form starts (a TOML file never starts with `{`).
pub const BUILT_PREFIX: &str = "{\"plc_exercise\":1,";

/// Whether `text` is an exercise in the built form (else it is TOML).
pub fn is_built(text: &str) -> bool {
    text.starts_with(BUILT_PREFIX)
}

/// The exercise file `toml_text` in the built form, its statement rendered by `render`
/// (Markdown to HTML). Only the TOML syntax is checked here: the exercise is checked when
/// it is read.
pub fn built_form(toml_text: &str, render: fn(&str) -> String) -> Result<String, String> {
    let table: toml::Table = toml::from_str(toml_text).map_err(|e| e.message().to_string())?;
    let mut exercise = serde_json::Map::new();
    let mut html = String::new();
    for (key, value) in table {
        if key == "statement" {
            html = render(value.as_str().ok_or("the statement is not text")?);
            continue;
        }
        if key == "lang" {
            exercise.insert(key, json_of(rendered_translations(value, render)?)?);
            continue;
        }
        exercise.insert(key, json_of(value)?);
    }
    // `Value`'s Display writes compact JSON.
    Ok(format!(
        "{BUILT_PREFIX}\"statement_html\":{},\"exercise\":{}}}",
        serde_json::Value::String(html),
        serde_json::Value::Object(exercise)
    ))
}

/// The `lang` table with each translation's `statement` rendered, as `statement_html`.
fn rendered_translations(
    value: toml::Value,
    render: fn(&str) -> String,
) -> Result<toml::Value, String> {
    let toml::Value::Table(mut langs) = value else { return Err("`lang` is not a table".into()) };
    for (key, t) in langs.iter_mut() {
        let toml::Value::Table(t) = t else { return Err(format!("`lang.{key}` is not a table")) };
        if let Some(statement) = t.remove("statement") {
            let markdown = statement
                .as_str()
                .ok_or_else(|| format!("lang.{key}: the statement is not text"))?;
            t.insert("statement_html".into(), toml::Value::String(render(markdown)));
        }
    }
    Ok(toml::Value::Table(langs))
}

/// A TOML value as JSON (a date or time, which no exercise key takes, is refused).
fn json_of(value: toml::Value) -> Result<serde_json::Value, String> {
    Ok(match value {
        toml::Value::String(s) => serde_json::Value::String(s),
        toml::Value::Integer(i) => serde_json::Value::from(i),
        toml::Value::Float(f) => serde_json::Number::from_f64(f)
            .map(serde_json::Value::Number)
            .ok_or_else(|| format!("{f} cannot be written in JSON"))?,
        toml::Value::Boolean(b) => serde_json::Value::Bool(b),
        toml::Value::Datetime(d) => return Err(format!("{d}: no exercise key takes a date")),
        toml::Value::Array(items) => {
            serde_json::Value::Array(items.into_iter().map(json_of).collect::<Result<_, _>>()?)
        }
        toml::Value::Table(table) => serde_json::Value::Object(
            table.into_iter().map(|(k, v)| Ok((k, json_of(v)?))).collect::<Result<_, String>>()?,
        ),
    })
}
