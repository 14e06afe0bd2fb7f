//! A plant's scene (`docs/plants.md`, "Scenes"): widgets placed on a canvas and bound to
//! variables, which the web app draws from the values of each scan. Buttons and switches
//! write the controller's inputs as the I/O panel does.

use serde::{Deserialize, Serialize};

/// A scene: a canvas and its widgets.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Scene {
    /// The canvas width.
    pub width: f64,
    /// The canvas height.
    pub height: f64,
    /// The widgets, drawn in this order.
    pub widgets: Vec<Widget>,
}

/// One widget of a scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Widget {
    /// What it draws.
    pub kind: WidgetKind,
    /// Its name, the start of its accessible name (`Tank T1`, `Start`).
    pub label: String,
    /// The variable it shows or writes (`Weight`, `WeighingPlant.Content`).
    pub var: String,
    /// Its top-left corner.
    pub x: f64,
    /// Its top-left corner.
    pub y: f64,
    /// Its size.
    #[serde(default = "default_size")]
    pub width: f64,
    /// Its size.
    #[serde(default = "default_size")]
    pub height: f64,
    /// The value that fills a tank or a gauge (100 %), or a scale's range.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max: Option<f64>,
    /// The unit written after a readout's value (`g`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub unit: Option<String>,
    /// A readout's value is the variable's divided by this (`10` for grams × 10).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub scale: Option<f64>,
    /// A tank's overflow (a BOOL): while TRUE the tank spills and its name says
    /// `overflow`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alarm: Option<String>,
    /// A conveyor's item position (0 to `max` along the belt); no item while negative.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub at: Option<String>,
    /// A traffic light's yellow lamp (its red lamp is `var`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub yellow: Option<String>,
    /// A traffic light's green lamp.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub green: Option<String>,
}

fn default_size() -> f64 {
    40.0
}

/// The kinds of widget.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum WidgetKind {
    /// A vessel filled to the variable's share of `max`.
    Tank,
    /// A valve, open while its BOOL is TRUE.
    Valve,
    /// A motor (a mixer, a fan), running while its BOOL is TRUE.
    Motor,
    /// A pump, running while its BOOL is TRUE.
    Pump,
    /// A conveyor belt, moving while its BOOL is TRUE, with an item at `at`.
    Conveyor,
    /// A photo-eye (light barrier): its BOOL is TRUE while something blocks the beam.
    PhotoEye,
    /// A limit switch: its BOOL is TRUE while it is pressed.
    LimitSwitch,
    /// A traffic light: red (`var`), yellow and green lamps.
    TrafficLight,
    /// A round gauge with a needle at the variable's share of `max`, and a readout.
    Gauge,
    /// A lamp, lit while its BOOL is TRUE.
    Lamp,
    /// A scale with a digital readout of its variable.
    Scale,
    /// A push button: holds its BOOL input TRUE while pressed (momentary).
    Button,
    /// A selector switch: toggles its BOOL input.
    Switch,
    /// A fault switch: turns one of the plant's faults on or off (a stuck sensor, a valve
    /// that does not open), for an instructor or a scenario to test the controller.
    Fault,
    /// A text with the variable's value.
    Text,
}

impl Scene {
    /// Every variable the scene's widgets are bound to: `(widget label, path)`, in widget
    /// order (a widget's `var`, then its `alarm`, `at`, `yellow` and `green`).
    pub fn bindings(&self) -> Vec<(&str, &str)> {
        let mut out = Vec::new();
        for w in &self.widgets {
            out.push((w.label.as_str(), w.var.as_str()));
            for extra in [&w.alarm, &w.at, &w.yellow, &w.green].into_iter().flatten() {
                out.push((w.label.as_str(), extra.as_str()));
            }
        }
        out
    }
}

impl WidgetKind {
    /// Whether the widget writes its variable (the controller's input).
    pub fn writes(self) -> bool {
        matches!(self, WidgetKind::Button | WidgetKind::Switch | WidgetKind::Fault)
    }
}
