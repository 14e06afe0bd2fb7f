//! The SVG of one rung: rails, wires, vertical links, contacts, coils, blocks, jumps, and
//! the marks of problems and faults. Colours follow the live power flow; an input contact
//! toggles its input when clicked.

use leptos::prelude::*;
use plc_core::build::Site;
use plc_core::ladder::{Block, CoilKind, ContactKind, Element, Rung};

use super::geometry::{
    clip, pin_lines, rung_geometry, runs_to_right_rail, NodePower, PinLine, RungGeometry, RAIL_X,
};
use super::live::LadderLive;
use crate::i18n::{t, tf, K};
use crate::state::AppState;

/// Characters of an operand shown above a contact or coil.
const OPERAND_CHARS: usize = 13;
/// Characters of a line inside a block.
const BLOCK_CHARS: usize = 22;

/// What every part of a rung's drawing shares (all handles, so it is `Copy`).
#[derive(Clone, Copy)]
pub struct RungCtx {
    /// The app state.
    pub state: AppState,
    /// The POU's live state (`None` when it is not running).
    pub live: Memo<Option<LadderLive>>,
    /// The rung's node power (`None` when not running).
    pub nodes: Memo<Option<NodePower>>,
    /// The rung's index.
    pub rung: usize,
}

impl RungCtx {
    fn out_power(self, row: usize, col: usize) -> impl Fn() -> bool + Copy + Send + Sync + 'static {
        move || self.live.with(|l| l.as_ref().is_some_and(|l| l.powered(self.rung, row, col)))
    }

    fn node_power(
        self,
        row: usize,
        col: usize,
    ) -> impl Fn() -> bool + Copy + Send + Sync + 'static {
        move || self.nodes.with(|n| n.as_ref().is_some_and(|n| n.at(row, col)))
    }

    fn is_live(self) -> bool {
        self.live.with(Option::is_some)
    }
}

fn hline(
    x1: f64,
    x2: f64,
    y: f64,
    powered: impl Fn() -> bool + Send + Sync + 'static,
) -> impl IntoView {
    view! { <line class="ld-wire" class:powered=powered x1=x1 y1=y x2=x2 y2=y/> }
}

/// The operand as a stored key, and its live BOOL value.
fn operand_state(
    ctx: RungCtx,
    operand: &str,
) -> (StoredValue<String>, impl Fn() -> Option<bool> + Copy + Send + Sync + 'static) {
    let key = StoredValue::new(operand.to_string());
    let value =
        move || ctx.live.with(|l| l.as_ref().and_then(|l| key.with_value(|k| l.bool_of(k))));
    (key, value)
}

fn contact_letter(kind: ContactKind) -> Option<&'static str> {
    match kind {
        ContactKind::Rising => Some("P"),
        ContactKind::Falling => Some("N"),
        ContactKind::NormallyOpen | ContactKind::NormallyClosed => None,
    }
}

/// The letter drawn inside a coil of `kind` (`S`, `R`, `/`, `P`, `N`; none for a plain one).
pub(crate) fn coil_letter(kind: CoilKind) -> &'static str {
    match kind {
        CoilKind::Normal => "",
        CoilKind::Negated => "/",
        CoilKind::Set => "S",
        CoilKind::Reset => "R",
        CoilKind::Rising => "P",
        CoilKind::Falling => "N",
    }
}

fn kind_name(kind: ContactKind) -> &'static str {
    t(match kind {
        ContactKind::NormallyOpen => K::ladder_kind_no,
        ContactKind::NormallyClosed => K::ladder_kind_nc,
        ContactKind::Rising => K::ladder_kind_rising,
        ContactKind::Falling => K::ladder_kind_falling,
    })
}

fn contact(
    ctx: RungCtx,
    geo: &RungGeometry,
    (row, col): (usize, usize),
    kind: ContactKind,
    operand: &str,
) -> AnyView {
    let (x0, x1) = geo.col_span(col);
    let (cx, y) = ((x0 + x1) / 2.0, geo.wire_y(row));
    let op = operand.trim().to_string();
    let (key, value) = operand_state(ctx, &op);
    let toggles =
        move || ctx.live.with(|l| l.as_ref().is_some_and(|l| key.with_value(|k| l.is_input(k))));
    let toggle = move || {
        if toggles() {
            let on = value().unwrap_or(false);
            key.with_value(|k| ctx.state.hold_input(k, if on { "FALSE" } else { "TRUE" }));
        }
    };
    let label = tf(K::ladder_contact, &[("operand", &op)]);
    let title = move || {
        let v = value().map(|v| if v { " = TRUE" } else { " = FALSE" }).unwrap_or("");
        let hint =
            if toggles() { format!(" ({})", t(K::ladder_click_to_toggle)) } else { String::new() };
        format!("{op}{v}: {}{hint}", kind_name(kind))
    };
    view! {
        <g class="ld-el ld-contact" class:powered=ctx.out_power(row, col)
            class:toggles=toggles
            data-cell=format!("{}-{row}-{col}", ctx.rung)
            role=move || if toggles() { "button" } else { "img" }
            tabindex=move || if toggles() { "0" } else { "-1" }
            aria-label=label
            aria-pressed=move || toggles().then(|| if value().unwrap_or(false) { "true" } else { "false" })
            on:click=move |_| toggle()
            on:keydown=move |ev| {
                if ev.key() == "Enter" || ev.key() == " " {
                    ev.prevent_default();
                    toggle();
                }
            }>
            <title>{title}</title>
            {hline(x0, cx - 8.0, y, ctx.node_power(row, col))}
            {hline(cx + 8.0, x1, y, ctx.out_power(row, col))}
            <rect class="ld-state" class:on=move || value() == Some(true)
                x=cx - 8.0 y=y - 12.0 width="16" height="24"/>
            <line class="ld-sym" x1=cx - 8.0 y1=y - 13.0 x2=cx - 8.0 y2=y + 13.0/>
            <line class="ld-sym" x1=cx + 8.0 y1=y - 13.0 x2=cx + 8.0 y2=y + 13.0/>
            {(kind == ContactKind::NormallyClosed).then(|| view! {
                <line class="ld-sym" x1=cx - 7.0 y1=y + 11.0 x2=cx + 7.0 y2=y - 11.0/>
            })}
            {contact_letter(kind).map(|l| view! {
                <text class="ld-letter" x=cx y=y + 4.0>{l}</text>
            })}
            <text class="ld-operand" x=cx y=y - 19.0>{clip(operand.trim(), OPERAND_CHARS)}</text>
        </g>
    }
    .into_any()
}

fn coil(
    ctx: RungCtx,
    geo: &RungGeometry,
    (row, col): (usize, usize),
    kind: CoilKind,
    operand: &str,
) -> AnyView {
    let (x0, x1) = geo.col_span(col);
    let (cx, y) = ((x0 + x1) / 2.0, geo.wire_y(row));
    let op = operand.trim().to_string();
    let (_, value) = operand_state(ctx, &op);
    let name = op.clone();
    let label = move || match value() {
        Some(v) => {
            tf(if v { K::ladder_coil_on } else { K::ladder_coil_off }, &[("operand", &name)])
        }
        None => tf(K::ladder_coil, &[("operand", &name)]),
    };
    view! {
        <g class="ld-el ld-coil" class:powered=ctx.out_power(row, col)
            data-cell=format!("{}-{row}-{col}", ctx.rung) role="img" aria-label=label>
            <title>{tf(K::ladder_coil_title, &[("operand", &op)])}</title>
            {hline(x0, cx - 10.0, y, ctx.node_power(row, col))}
            {hline(cx + 10.0, x1, y, ctx.out_power(row, col))}
            <circle class="ld-state" class:on=move || value() == Some(true) cx=cx cy=y r="11"/>
            <path class="ld-sym" d=format!("M{} {} Q{} {y} {} {}", cx - 5.0, y - 12.0, cx - 13.0, cx - 5.0, y + 12.0)/>
            <path class="ld-sym" d=format!("M{} {} Q{} {y} {} {}", cx + 5.0, y - 12.0, cx + 13.0, cx + 5.0, y + 12.0)/>
            <text class="ld-letter" x=cx y=y + 4.0>{coil_letter(kind)}</text>
            <text class="ld-operand" x=cx y=y - 19.0>{clip(operand.trim(), OPERAND_CHARS)}</text>
        </g>
    }
    .into_any()
}

/// The text of one line of a block, with the live value when there is one.
fn pin_text(block: &Block, line: &PinLine, live: Option<&LadderLive>) -> (String, bool) {
    let with_value = |text: String, operand: &str| match live.and_then(|l| l.value_of(operand)) {
        Some(v) if !v.eq_ignore_ascii_case(operand.trim()) => format!("{text} = {v}"),
        _ => text,
    };
    match line {
        PinLine::Power { .. } => (String::new(), false),
        PinLine::Input(i) => block.inputs.get(*i).map_or((String::new(), false), |p| {
            (with_value(format!("{}: {}", p.name, p.operand.trim()), &p.operand), false)
        }),
        PinLine::InOut(i) => block.in_outs.get(*i).map_or((String::new(), false), |p| {
            (with_value(format!("{} ↔ {}", p.name, p.operand.trim()), &p.operand), true)
        }),
        PinLine::Output(i) => block.outputs.get(*i).map_or((String::new(), true), |p| {
            (with_value(format!("{} → {}", p.name, p.operand.trim()), &p.operand), true)
        }),
        PinLine::Instance(name) => {
            let path = format!("{}.{name}", block.instance.as_deref().unwrap_or_default().trim());
            (with_value(name.to_string(), &path), true)
        }
    }
}

fn block(ctx: RungCtx, geo: &RungGeometry, (row, col): (usize, usize), b: &Block) -> AnyView {
    let (x0, x1) = geo.col_span(col);
    let (left, top, right, bottom) = geo.block_box(b, row, col);
    let y = geo.wire_y(row);
    let cx = (left + right) / 2.0;
    let lines = pin_lines(b);
    let shared = StoredValue::new(b.clone());
    let line_views = lines
        .iter()
        .enumerate()
        .map(|(k, line)| {
            let ly = geo.pin_y(row, k);
            if let PinLine::Power { input, output } = line {
                return view! {
                    <text class="ld-pin" x=left + 4.0 y=ly + 4.0>{input.clone()}</text>
                    <text class="ld-pin end" x=right - 4.0 y=ly + 4.0>{output.clone()}</text>
                }
                .into_any();
            }
            let line = line.clone();
            let text = move || {
                let (t, _) =
                    ctx.live.with(|l| shared.with_value(|b| pin_text(b, &line, l.as_ref())));
                clip(&t, BLOCK_CHARS)
            };
            let right_side = shared.with_value(|b| pin_text(b, &lines[k], None).1);
            let (x, class) =
                if right_side { (right - 4.0, "ld-pin end") } else { (left + 4.0, "ld-pin") };
            view! { <text class=class x=x y=ly + 4.0>{text}</text> }.into_any()
        })
        .collect_view();
    let wired = b
        .inputs
        .iter()
        .filter_map(|p| {
            let w = p.wired_row? as usize;
            let wy = geo.wire_y(row + w);
            Some(view! {
                {hline(x0, left, wy, ctx.node_power(row + w, col))}
                <text class="ld-pin" x=left + 4.0 y=wy + 4.0>{p.name.clone()}</text>
            })
        })
        .collect_view();
    let title = match &b.instance {
        Some(i) => format!("{i}: {}", b.type_name),
        None => b.type_name.clone(),
    };
    view! {
        <g class="ld-el ld-block" class:powered=ctx.out_power(row, col)
            data-cell=format!("{}-{row}-{col}", ctx.rung) role="img" aria-label=tf(K::ladder_block, &[("block", &title)])>
            <title>{title.clone()}</title>
            {hline(x0, left, y, ctx.node_power(row, col))}
            {hline(right, x1, y, ctx.out_power(row, col))}
            <rect class="ld-box" x=left y=top width=right - left height=bottom - top rx="3"/>
            {wired}
            <text class="ld-block-type" x=cx y=top + 13.0>{clip(&b.type_name, BLOCK_CHARS)}</text>
            {b.instance.clone().map(|i| view! {
                <text class="ld-operand" x=cx y=top - 5.0>{clip(&i, BLOCK_CHARS)}</text>
            })}
            {line_views}
        </g>
    }
    .into_any()
}

fn simple(
    ctx: RungCtx,
    geo: &RungGeometry,
    (row, col): (usize, usize),
    element: &Element,
) -> AnyView {
    let (x0, x1) = geo.col_span(col);
    let (cx, y) = ((x0 + x1) / 2.0, geo.wire_y(row));
    let cell = format!("{}-{row}-{col}", ctx.rung);
    match element {
        Element::Wire => view! {
            <g class="ld-el" class:powered=ctx.out_power(row, col) data-cell=cell>
                {hline(x0, x1, y, ctx.out_power(row, col))}
            </g>
        }
        .into_any(),
        Element::Jump { label } => view! {
            <g class="ld-el ld-jump" class:powered=ctx.out_power(row, col) data-cell=cell
                role="img" aria-label=tf(K::ladder_jump_to, &[("label", label)])>
                {hline(x0, cx - 12.0, y, ctx.node_power(row, col))}
                <text class="ld-letter start" x=cx - 10.0 y=y + 4.0>{format!("»{}", clip(label, 9))}</text>
            </g>
        }
        .into_any(),
        Element::Return => view! {
            <g class="ld-el ld-jump" class:powered=ctx.out_power(row, col) data-cell=cell
                role="img" aria-label=t(K::ladder_tool_return)>
                {hline(x0, cx - 18.0, y, ctx.node_power(row, col))}
                <text class="ld-letter start" x=cx - 16.0 y=y + 4.0>"RETURN"</text>
            </g>
        }
        .into_any(),
        _ => ().into_any(),
    }
}

/// The marks of a cell: a problem, the fault, the cell a clicked problem points at. They
/// follow the problems as a check finds them, without drawing the rung again (a rung whose
/// cells were replaced under the pointer would lose what the user was about to drag).
fn marks(ctx: RungCtx, geo: &RungGeometry, pou: &str) -> impl IntoView {
    let geo_diag = geo.clone();
    let pou_diag = pou.to_string();
    let diag_views = move || {
        let cell_rect = |row: usize, col: usize| {
            let (x0, x1) = geo_diag.col_span(col);
            let top = geo_diag.row_h * row as f64;
            (x0 + 2.0, top + 2.0, x1 - x0 - 4.0, geo_diag.row_h - 4.0)
        };
        let diags = ctx.state.diagnostics.with(|ds| {
            ds.iter()
                .filter_map(|d| match &d.site {
                    Site::Ladder { pou: p, cell: Some((r, row, col)) }
                        if p.eq_ignore_ascii_case(&pou_diag) && *r == ctx.rung =>
                    {
                        Some((*row, *col, d.error, format!("{} {}", d.code, d.message())))
                    }
                    _ => None,
                })
                .collect::<Vec<_>>()
        });
        diags
            .into_iter()
            .map(|(row, col, error, text)| {
                let (x, y, w, h) = cell_rect(row, col);
                let class = if error { "ld-diag err" } else { "ld-diag warn" };
                view! { <rect class=class x=x y=y width=w height=h rx="4"><title>{text}</title></rect> }
            })
            .collect_view()
    };
    let pou_name = pou.to_string();
    let mark = move |site: Option<Site>, class: &'static str| {
        let cell = match site {
            Some(Site::Ladder { pou, cell: Some((r, row, col)) })
                if pou.eq_ignore_ascii_case(&pou_name) && r == ctx.rung =>
            {
                Some((row, col))
            }
            _ => None,
        };
        cell.map(|(row, col)| (class, row, col))
    };
    let geo_focus = geo.clone();
    let geo_fault = geo.clone();
    let mark_focus = mark.clone();
    let rect_of = move |g: &RungGeometry, row: usize, col: usize| {
        let (x0, x1) = g.col_span(col);
        let top = g.row_h * row as f64;
        (x0 + 1.0, top + 1.0, x1 - x0 - 2.0, g.row_h - 2.0)
    };
    view! {
        {diag_views}
        {move || mark_focus(ctx.state.focus.get(), "ld-focus").map(|(class, row, col)| {
            let (x, y, w, h) = rect_of(&geo_focus, row, col);
            view! { <rect class=class x=x y=y width=w height=h rx="5"/> }
        })}
        {move || mark(ctx.state.fault_site.get(), "ld-fault").map(|(class, row, col)| {
            let (x, y, w, h) = rect_of(&geo_fault, row, col);
            view! { <rect class=class x=x y=y width=w height=h rx="5"><title>{t(K::ladder_fault_here)}</title></rect> }
        })}
    }
}

/// The SVG of rung `ctx.rung` of POU `pou`.
pub fn rung_svg(ctx: RungCtx, rung: &Rung, pou: &str) -> impl IntoView {
    let geo = rung_geometry(rung);
    let rows = rung.rows();
    let mut parts = Vec::new();
    for row in 0..rows {
        for (col, cell) in rung.cells[row].iter().enumerate() {
            if cell.link_down && row + 1 < rows {
                let x = geo.col_x.get(col).copied().unwrap_or(RAIL_X);
                let (y1, y2) = (geo.wire_y(row), geo.wire_y(row + 1));
                let powered = ctx.node_power(row, col);
                parts.push(
                    view! { <line class="ld-wire ld-link" class:powered=powered x1=x y1=y1 x2=x y2=y2/> }
                        .into_any(),
                );
            }
            let at = (row, col);
            let view = match &cell.element {
                Element::Contact { kind, operand } => contact(ctx, &geo, at, *kind, operand),
                Element::Coil { kind, operand } => coil(ctx, &geo, at, *kind, operand),
                Element::Block(b) => block(ctx, &geo, at, b),
                other => simple(ctx, &geo, at, other),
            };
            parts.push(view);
            if runs_to_right_rail(rung, row, col) {
                let (_, x1) = geo.col_span(col);
                parts.push(
                    hline(x1, geo.right_rail_x, geo.wire_y(row), ctx.out_power(row, col))
                        .into_any(),
                );
            }
        }
    }
    let live = move || ctx.is_live();
    view! {
        <svg class="ld-rung-svg" viewBox=format!("0 0 {} {}", geo.width, geo.height)
            width=geo.width height=geo.height style=format!("--ld-w:{}", geo.width) role="group"
            aria-label=tf(K::ladder_rung, &[("rung", &(ctx.rung + 1).to_string())])>

            <line class="ld-rail" class:powered=live x1=RAIL_X y1="2" x2=RAIL_X y2=geo.height - 2.0/>
            <line class="ld-rail" x1=geo.right_rail_x y1="2" x2=geo.right_rail_x y2=geo.height - 2.0/>
            {parts}
            {marks(ctx, &geo, pou)}
        </svg>
    }
}
