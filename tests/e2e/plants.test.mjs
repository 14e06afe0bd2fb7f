// Plants (issue 17): a project whose settings name a plant PROGRAM runs it after the
// controller on every scan; the plant drives the controller's sensor and its own
// variables are in the variable table under its name.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import { readFile } from 'node:fs/promises';
import { execFileSync } from 'node:child_process';
import { startServer } from './server.mjs';
import { launch } from './browser.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
let server;
let browser;

before(async () => {
  server = await startServer(path.join(root, 'dist'));
  browser = await launch();
});
after(async () => {
  await browser?.close();
  await server?.close();
});

const TANK = JSON.stringify({
  schema: 1,
  name: 'Tank',
  source: `PROGRAM Control
VAR_INPUT Level : INT; END_VAR
VAR_OUTPUT Fill : BOOL; END_VAR
IF Level < 40 THEN Fill := TRUE; ELSIF Level > 60 THEN Fill := FALSE; END_IF;
END_PROGRAM
PROGRAM Tank
VAR_INPUT Fill : BOOL; END_VAR
VAR_OUTPUT Level : INT; END_VAR
VAR Scans : INT; END_VAR
IF Fill THEN Level := Level + 5; ELSIF Level > 0 THEN Level := Level - 1; END_IF;
Scans := Scans + 1;
END_PROGRAM
`,
  settings: { cycle_ms: 10, traced: [], breakpoints: [], program: 'Control', plant: 'Tank' },
});

test('the plant named in the settings runs after the controller and drives its sensor', async () => {
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor({ state: 'attached' });
  await page.getByLabel('Import project file').setInputFiles({
    name: 'tank.plcproj.json', mimeType: 'application/json', buffer: Buffer.from(TANK),
  });
  const vars = page.getByRole('region', { name: 'Variables' });
  await vars.getByRole('rowheader', { name: /Tank/ }).waitFor();
  const step = page.getByRole('button', { name: 'Step', exact: true });
  for (let k = 0; k < 4; k += 1) await step.click();
  // Four scans of filling: the plant raised the level by 5 each, and the controller's
  // sensor reads it.
  const value = (name) => vars.getByRole('row').filter({ has: page.getByRole('rowheader', { name, exact: true }) }).getByRole('cell').nth(3);
  assert.equal((await value('Level').textContent()).trim(), '20');
  assert.equal((await value('Fill').textContent()).trim(), 'TRUE');
  await vars.getByRole('button', { name: 'Expand Tank' }).click();
  assert.equal((await value('Scans').textContent()).trim(), '4');
  assert.deepEqual(errors, []);
  await context.close();
});

test('the weighing plant: the scene\'s Start button starts a batch and the scale climbs to the set point', async () => {
  const { context, page, errors, scene } = await openExample('Weighing with its plant (Petri net and ST plant)');
  await scene.getByRole('img', { name: 'Scale: 0 g' }).waitFor();
  await scene.getByRole('img', { name: 'Feed valve: closed' }).waitFor();
  // Pressed while paused, the button holds Start until a scan has seen it.
  await scene.getByRole('button', { name: 'Start button' }).click();
  const step = page.getByRole('button', { name: 'Step', exact: true });
  for (let k = 0; k < 3; k += 1) await step.click();
  await scene.getByRole('img', { name: 'Feed valve: open' }).waitFor();
  assert.equal(await scene.getByRole('button', { name: 'Start button' }).getAttribute('aria-pressed'), 'false');
  // The Petri view's token moved from the idle place P1 to the filling place P31.
  const net = page.getByRole('region', { name: 'Petri net Weighing' });
  await net.getByRole('button', { name: /^Place P31\b.*: 1 token$/ }).waitFor();
  await net.getByRole('button', { name: /^Place P1\b.*: 0 tokens$/ }).waitFor();
  const scale = async () => Number((await scene.getByRole('img', { name: /^Scale: / }).getAttribute('aria-label')).match(/Scale: ([0-9.]+) g/)[1]);
  const before = await scale();
  for (let k = 0; k < 5; k += 1) await step.click();
  assert.ok(await scale() > before, 'the scale climbs while the feed valve is open');
  // 200 scans more: filled to the set point (50 g) and settling, the valve closed.
  await page.getByRole('spinbutton', { name: 'Scans per step' }).fill('200');
  await page.getByRole('button', { name: 'Step N' }).click();
  await scene.getByRole('img', { name: 'Feed valve: closed' }).waitFor();
  const filled = await scale();
  assert.ok(filled >= 50 && filled <= 50.5, `the scale stops at the set point, not ${filled}`);
  await scene.getByRole('img', { name: 'Hopper: 50 %' }).waitFor();
  // After the 2 s settling time: discharging into the running mixer.
  await page.getByRole('spinbutton', { name: 'Scans per step' }).fill('150');
  await page.getByRole('button', { name: 'Step N' }).click();
  await scene.getByRole('img', { name: 'Discharge valve: open' }).waitFor();
  await scene.getByRole('img', { name: 'Mixer: running' }).waitFor();
  await net.getByRole('button', { name: /^Place P33\b.*: 1 token$/ }).waitFor();
  await net.getByRole('button', { name: /^Place P31\b.*: 0 tokens$/ }).waitFor();
  // Scan by scan, the timeline holds what plc run records for the same 358 scans (Start
  // matters only in the idle place, so the press and a held Start run alike).
  const download = page.waitForEvent('download');
  await page.getByRole('region', { name: 'Timeline' }).getByRole('button', { name: 'Export CSV' }).click();
  const browserCsv = await readFile(await (await download).path(), 'utf8');
  const cliCsv = plc(['run', path.join(root, 'examples/weighing-plant.plcproj.json'), '--cycles', '358', '--set', 'Start=TRUE', '--csv']);
  assert.equal(browserCsv.split('\r\n').length, 360, browserCsv.slice(0, 200));
  assert.equal(browserCsv, cliCsv);
  await page.screenshot({ path: path.join(root, 'docs/screenshots/plant-weighing.png'), fullPage: true });
  assert.deepEqual(errors, []);
  await context.close();
});

/** `plc ARGS…` from the workspace (built by `cargo test` before the browser tests). */
function plc(args) {
  return execFileSync('cargo', ['run', '-q', '-p', 'plc-core', '--bin', 'plc', '--', ...args], { cwd: root }).toString();
}

/** Opens the shipped example titled `title` in a fresh page. */
async function openExample(title) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 1000 }, acceptDownloads: true });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor({ state: 'attached' });
  await page.getByRole('combobox', { name: 'Open example' }).selectOption({ label: title });
  return { context, page, errors, scene: page.getByRole('region', { name: 'Plant' }) };
}

/** Runs `n` scans with the Step N button. */
async function stepN(page, n) {
  await page.getByRole('spinbutton', { name: 'Scans per step' }).fill(String(n));
  await page.getByRole('button', { name: 'Step N' }).click();
}

test('the tank: the browser and plc run give the same values scan by scan, a plant hour passes without a fault, and the wrong controller runs it over', async () => {
  const { context, page, errors, scene } = await openExample('Tank with level switches (ST plant)');
  await scene.getByRole('img', { name: 'Tank T1: 30 %' }).waitFor();
  // The level switches are the plant's sensors: shown as lamps, not offered as inputs.
  const io = page.getByRole('region', { name: 'Inputs and outputs' });
  await io.getByRole('img', { name: 'HighSwitch: OFF' }).waitFor();
  assert.equal(await io.getByRole('checkbox', { name: 'HighSwitch', exact: true }).count(), 0);
  assert.equal(await io.getByText('from TankPlant').count(), 2);
  await io.getByRole('checkbox', { name: 'Auto', exact: true }).waitFor();
  await scene.getByRole('switch', { name: 'Auto switch' }).click();
  await stepN(page, 500);
  await page.getByText('Scan 500', { exact: false }).waitFor();
  await scene.getByRole('img', { name: 'Pump: running' }).waitFor();
  // The timeline's CSV is what `plc run --csv` prints for the same run.
  const download = page.waitForEvent('download');
  await page.getByRole('region', { name: 'Timeline' }).getByRole('button', { name: 'Export CSV' }).click();
  const browserCsv = await readFile(await (await download).path(), 'utf8');
  const cliCsv = plc(['run', path.join(root, 'examples/tank-plant.plcproj.json'), '--cycles', '500', '--set', 'Auto=TRUE', '--csv']);
  assert.equal(browserCsv.split('\r\n').length, 502, browserCsv.slice(0, 200));
  assert.equal(browserCsv, cliCsv);
  // The rest of a plant hour (360 000 scans of 10 ms): never over the rim, no alarm.
  await stepN(page, 359_500);
  await page.getByText('Scan 360000', { exact: false }).waitFor({ timeout: 60_000 });
  const fills = await scene.getByRole('img', { name: /^Fills: / }).getAttribute('aria-label');
  const count = Number(fills.match(/Fills: (\d+)/)[1]);
  assert.ok(count >= 58 && count <= 64, fills);
  assert.doesNotMatch(await scene.getByRole('img', { name: /^Tank T1: / }).getAttribute('aria-label'), /overflow/);
  await scene.getByRole('img', { name: 'Alarm: off' }).waitFor();
  const json = JSON.parse(plc(['run', path.join(root, 'examples/tank-plant.plcproj.json'), '--cycles', '360000', '--set', 'Auto=TRUE', '--json']));
  assert.equal(json.vars.TankPlant.Faults, 0);
  assert.equal(json.vars.TankPlant.Fills, count, 'the CLI counts the same fills');
  // The controller with the mistake: chosen under Program, restarted, it overflows.
  await page.getByRole('combobox', { name: 'Program to run' }).selectOption('TankWrong');
  await page.getByRole('button', { name: 'Reset', exact: true }).click();
  // Drawn down to the low switch (7.5 s), then filled for good (850 l at 30 l/s net).
  await stepN(page, 6000);
  await scene.getByRole('img', { name: 'Tank T1: overflow' }).waitFor();
  await page.screenshot({ path: path.join(root, 'docs/screenshots/plant-tank.png'), fullPage: true });
  assert.deepEqual(errors, []);
  await context.close();
});

/** The shipped plants: each runs a plant hour with its reference controller. */
const PLANT_HOURS = [
  { title: 'Weighing with its plant (Petri net and ST plant)', file: 'weighing-plant', press: ['Start'], set: ['Start=TRUE'], counters: [['Batches', 'WeighingPlant.Batches']], faults: null, quiet: 'Alarm: off' },
  { title: 'Conveyor with photo-eye and reject pusher (ST plant)', file: 'conveyor-plant', press: ['Start'], set: ['Start=TRUE'], counters: [['Good', 'ConveyorPlant.Good'], ['Rejected', 'ConveyorPlant.Rejected']], faults: 'ConveyorPlant' },
  { title: 'Pedestrian crossing with request button (ST plant)', file: 'traffic-crossing', press: [], set: [], counters: [['Crossings', 'CrossingPlant.Crossings'], ['Cars passed', 'CrossingPlant.Cars']], faults: 'CrossingPlant' },
  { title: 'Garage door with limit switches and obstruction sensor (ST plant)', file: 'garage-door', press: [], set: [], counters: [['Cycles', 'DoorPlant.Cycles'], ['Cars', 'DoorPlant.Cars']], faults: 'DoorPlant' },
  { title: 'Star-delta motor starter (ST plant)', file: 'star-delta', press: [], set: [], counters: [['Starts', 'MotorPlant.Starts']], faults: 'MotorPlant' },
];

/** The number a scene readout (`Label: 42`) shows. */
async function readout(scene, label) {
  const name = await scene.getByRole('img', { name: new RegExp(`^${label}: `) }).getAttribute('aria-label');
  return Number(name.slice(label.length + 2));
}

/** `vars` at a dotted path (`Plant.Name`). */
const at = (vars, dotted) => dotted.split('.').reduce((v, k) => v?.[k], vars);

test('every shipped plant runs a plant hour in the browser without a fault, with the counts plc run gives', async () => {
  for (const p of PLANT_HOURS) {
    const { context, page, errors, scene } = await openExample(p.title);
    await scene.waitFor();
    for (const b of p.press) await scene.getByRole('button', { name: `${b} button` }).click();
    await stepN(page, 360_000);
    await page.getByText('Scan 360000', { exact: false }).waitFor({ timeout: 60_000 });
    const cli = JSON.parse(plc(['run', path.join(root, `examples/${p.file}.plcproj.json`), '--cycles', '360000', ...p.set.flatMap((s) => ['--set', s]), '--json'])).vars;
    if (p.quiet) await scene.getByRole('img', { name: p.quiet }).waitFor();
    if (p.faults) {
      assert.equal(await readout(scene, 'Faults'), 0, `${p.title}: faults in the browser`);
      assert.equal(at(cli, `${p.faults}.Faults`), 0, `${p.title}: faults on the command line`);
    }
    for (const [label, variable] of p.counters) {
      const shown = await readout(scene, label);
      assert.ok(shown > 0, `${p.title}: ${label} counted nothing`);
      assert.equal(shown, at(cli, variable), `${p.title}: ${label} in the browser and ${variable} from plc run`);
    }
    await page.screenshot({ path: path.join(root, `docs/screenshots/plant-${p.file}.png`), fullPage: false });
    assert.deepEqual(errors, [], p.title);
    await context.close();
  }
});

test('an exercise with a plant shows its scene beside the editor and grades against its own plant', async () => {
  const context = await browser.newContext({ viewport: { width: 1400, height: 1000 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  await page.getByRole('button', { name: 'Exercises', exact: true }).click();
  await page.getByRole('list', { name: 'Exercise list' }).getByRole('button', { name: 'Tank with level switches and a watchdog (plant)' }).click();
  const panel = page.getByRole('region', { name: 'Exercise' });
  await panel.getByRole('heading', { name: 'Tank with level switches and a watchdog (plant)' }).waitFor();
  const scene = page.getByRole('region', { name: 'Plant' });
  await scene.getByRole('img', { name: 'Tank T1: 30 %' }).waitFor();
  // The starter does nothing: the grader's plant never fills, so the fills expectation fails.
  await page.getByRole('button', { name: 'Check', exact: true }).click();
  const report = page.getByRole('region', { name: 'Report' });
  await report.waitFor();
  await report.getByText(/TankPlant\.Fills >= 9/).first().waitFor();
  // The reference controller in place of the starter's: every scenario passes.
  const source = await page.getByRole('textbox', { name: 'ST source' }).inputValue();
  const reference = await readFile(path.join(root, 'exercises/tank-plant/reference.st'), 'utf8');
  const solved = source.replace(/PROGRAM TankControl[\s\S]*?END_PROGRAM/, reference.slice(reference.indexOf('PROGRAM TankControl')));
  await page.getByRole('textbox', { name: 'ST source' }).fill(solved);
  await page.waitForTimeout(500);
  await page.getByRole('button', { name: 'Check', exact: true }).click();
  await page.getByText('Score 5 of 5').waitFor({ timeout: 60_000 });
  await page.screenshot({ path: path.join(root, 'docs/screenshots/exercise-plant.png') });
  assert.deepEqual(errors, []);
  await context.close();
});
