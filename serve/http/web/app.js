// The shopper's page: choices -> GET /api/render's parameters -> the picture of the
// shopper's own body (the made body, women's or men's) in the catalogue's garments, each in
// a size of the chart. Measurements are typed in cm and sent in metres; the catalogue (GET
// /api/catalogue, its "made" part) fills the lists for the chosen sex.
// "Fit map" draws the garments coloured by their stretch (fitmap=stretch: same drape).
// "Advise my size" asks GET /api/fit for the same measurements (only when pressed: a fit
// drapes three sizes, seconds), then shows the advised sizes as pictures of the same body,
// each in its ease map; choosing one puts that size on the main picture.
// "Turntable" posts 12 views of the main picture as render jobs (POST /api/render) and shows
// each as its job ends: the drape is made once, each view is a render only.
"use strict";

const state = { azimuth: 0, catalogue: null, timer: null, shown: 0, turntable: 0 };
const sex = () => byId("sex").value;
const madeStyles = () => state.catalogue.made.styles.filter((s) => s.sizes[sex()]);
const styleNamed = (name) => madeStyles().find((s) => s.name === name);
const byId = (id) => document.getElementById(id);
const measures = ["stature", "bust", "waist", "hips"];
const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
const TURNTABLE_VIEWS = 12;  // every 30 degrees
const ELEVATION = 5;         // degrees: the main picture's, a shopper's eye a little above the waist

function option(select, value, text) {
  const o = document.createElement("option");
  o.value = value;
  o.textContent = text || value;
  select.appendChild(o);
}

function element(tag, className, text) {
  const e = document.createElement(tag);
  if (className) e.className = className;
  if (text !== undefined) e.textContent = text;
  return e;
}

// ---- The shopper's words: names, measurements in cm, errors --------------------------------

// The measurement's name as the page's label says it ("Chest" for men).
function measureName(parameter) {
  const names = { stature: "Height", bust: byId("bust-name").textContent, chest: "Chest", waist: "Waist", hips: "Hips" };
  return names[parameter] || parameter.charAt(0).toUpperCase() + parameter.slice(1);
}

const cm = (metres) => Math.round(Number(metres) * 100);

// "0.76 to 1.12 (metres)" -> "76 to 112 cm"; other texts as they are.
function rangeInCm(accepted) {
  const m = /^([\d.]+) to ([\d.]+) \(metres\)/.exec(accepted || "");
  return m ? cm(m[1]) + " to " + cm(m[2]) + " cm" : accepted;
}

// The body the pictures show, in the shopper's words.
function bodyWords() {
  const [stature, bust, waist, hips] = measures.map((m) => byId(m).value);
  return (sex() === "male" ? "men's" : "women's") + " body of height " + stature +
         " cm, " + measureName("bust").toLowerCase() + " " + bust + ", waist " + waist + ", hips " + hips + " cm";
}

// A 422's line names the measurement MakeHuman gave up on and the nearest it reaches ("waist_girth
// 0.880 m is out of reach with the other measurements: the nearest is 0.790 m"): said in cm.
function unreachableWords(line) {
  const m = /(stature|bust_girth|waist_girth|hip_girth) ([\d.]+) m is out of reach.*?nearest is ([\d.]+) m/.exec(line);
  if (!m) return "These measurements cannot be made into one body together: change one of them. (" + line + ")";
  const parameter = { stature: "stature", bust_girth: "bust", waist_girth: "waist", hip_girth: "hips" }[m[1]];
  return measureName(parameter) + ": " + cm(m[2]) + " cm cannot be combined with your other measurements; " +
         "the nearest that works with them is " + cm(m[3]) + " cm.";
}

// An error answer's JSON (400, 422, 429, 503, ...) as a sentence saying what to change.
function errorWords(status, body) {
  if (status === 429 || status === 503) return "The fitting room is busy: try again in a moment.";
  if (status === 422) return unreachableWords(body.error || "");
  const parameter = body.parameter === "chest" ? "bust" : body.parameter;
  if (measures.includes(parameter)) {
    if (body.error === "out of range")
      return measureName(parameter) + ": " + cm(body.value) + " cm is outside what we can show (" +
             rangeInCm(body.accepted) + ").";
    return measureName(parameter) + ": type a number of cm (" + rangeInCm(body.accepted) + ").";
  }
  if (parameter) return measureName(parameter) + ": " + body.error + " (we take " + body.accepted + ").";
  return body.error || "Something went wrong (" + status + "): try again.";
}

// An answer that is not ok as the shopper's sentence.
async function errorOf(response) {
  const body = await response.json().catch(() => ({ error: response.statusText }));
  return errorWords(response.status, body);
}

// The first empty measurement, said before anything is asked of the server; "" when all are typed.
function missingMeasure() {
  for (const m of measures) {
    const input = byId(m);
    if (input.value.trim() === "" || !Number.isFinite(Number(input.value)))
      return measureName(m) + ": type a number of cm (" + input.min + " to " + input.max + " cm).";
  }
  return "";
}

// ---- The garments ----------------------------------------------------------------------------

function fillSizes(size, style) {
  const before = size.value;
  size.textContent = "";
  const sizes = style ? style.sizes[sex()] : [];
  sizes.forEach((s) => option(size, s));
  size.value = sizes.includes(before) ? before : sizes.includes("M") ? "M" : sizes[Math.floor(sizes.length / 2)] || "";
}

function fillGarment(index) {
  const style = byId("style-" + index);
  const before = style.value;
  style.textContent = "";
  option(style, "", "(none)");
  madeStyles().forEach((s) => option(style, s.name));
  style.value = styleNamed(before) ? before : "";
  fillSizes(byId("size-" + index), styleNamed(style.value));
}

// Garment row `index` wears `name` in its default colour and its middle size.
function wearStyle(index, name) {
  byId("style-" + index).value = name;
  byId("colour-" + index).value = "#" + styleNamed(name).defaultColour;
  fillSizes(byId("size-" + index), styleNamed(name));
}

function garmentRow(index) {
  const row = element("div", "garment");
  const style = element("select");
  style.id = "style-" + index;
  style.setAttribute("aria-label", "Garment " + (index + 1));
  const size = element("select");
  size.id = "size-" + index;
  size.setAttribute("aria-label", "Size of garment " + (index + 1));
  const colour = element("input");
  colour.type = "color";
  colour.id = "colour-" + index;
  colour.setAttribute("aria-label", "Colour of garment " + (index + 1));
  style.addEventListener("change", () => {
    const s = styleNamed(style.value);
    if (s) colour.value = "#" + s.defaultColour;
    fillSizes(size, s);
  });
  [style, size, colour].forEach((e) => { row.appendChild(e); e.addEventListener("change", schedule); });
  return row;
}

// The garment rows worn, innermost first: [{row, style, size, colour}].
function worn() {
  const items = [];
  for (let i = 0; byId("style-" + i); i++) {
    const style = byId("style-" + i).value;
    if (style) items.push({ row: i, style, size: byId("size-" + i).value, colour: byId("colour-" + i).value.slice(1) });
  }
  return items;
}

function outfit() {
  const items = worn().map((g) => g.style + ":" + g.size + ":" + g.colour);
  return items.length ? items.join(",") : "none";
}

function outfitWords() {
  const items = worn().map((g) => "the " + g.style + " in " + g.size);
  return items.length ? items.join(" under ") : "nothing";
}

// ---- The main picture ------------------------------------------------------------------------

// The body's parameters: sex, measurements in metres, skin and light; the pose when `posed`.
function bodyParameters(posed) {
  const p = new URLSearchParams();
  p.set("sex", sex());
  for (const m of measures) p.set(m, (Number(byId(m).value) / 100).toFixed(3));
  for (const k of posed ? ["skin", "pose", "light"] : ["skin", "light"]) p.set(k, byId(k).value);
  if (!byId("underwear").checked) p.set("underwear", "off");  // on is the server's default
  return p;
}

// The main picture's parameters seen from `azimuth`.
function query(azimuth) {
  const p = bodyParameters(true);
  p.set("outfit", outfit());
  if (byId("fitmap").checked) p.set("fitmap", "stretch");
  p.set("view", azimuth + "," + ELEVATION);
  p.set("size", "480x640");
  return p.toString();
}

const SIDES = { 0: "front", 90: "right", 180: "back", 270: "left" };
const angleName = (azimuth) => SIDES[azimuth] || azimuth + "°";
const viewWords = (azimuth) => (SIDES[azimuth] ? "the " + SIDES[azimuth] : azimuth + "°");

async function show() {
  const problem = missingMeasure();
  if (problem) { byId("error").textContent = problem; return; }
  const url = "/api/render?" + query(state.azimuth);
  const ticket = ++state.shown;  // a slower earlier answer must not replace a later one
  byId("status").textContent = "Draping…";
  byId("error").textContent = "";
  byId("drape-note").textContent = "";
  const response = await fetch(url);
  if (ticket !== state.shown) return;
  if (!response.ok) {
    byId("error").textContent = await errorOf(response);
    byId("status").textContent = "";
    return;
  }
  const blob = await response.blob();
  if (ticket !== state.shown) return;
  const img = byId("picture");
  if (img.dataset.url) URL.revokeObjectURL(img.dataset.url);
  img.dataset.url = URL.createObjectURL(blob);
  img.dataset.query = url;
  img.alt = "Your " + bodyWords() + ", in " + outfitWords() + ", seen from " + viewWords(state.azimuth);
  byId("glb").href = url + "&format=glb";
  img.src = img.dataset.url;
  byId("status").textContent = "Shown (" + (response.headers.get("X-Figment-Cache") || "") + ")";
  byId("drape-note").textContent = drapeNote(response.headers.get("X-Figment-Drape"));
}

// What the shopper is told when the drape the picture shows may be wrong (X-Figment-Drape).
function drapeNote(drape) {
  if (drape === "torn")
    return "This outfit did not drape cleanly: the cloth was stretched past what it takes somewhere, " +
           "so the picture may not show how it would wear.";
  if (drape === "restless")
    return "This outfit had not quite settled when the picture was taken: it may hang a little differently.";
  return "";
}

// A choice changed: the turntable's views are of the old picture; the new one is asked
// for a moment later, so typing a number asks once.
function schedule() {
  stopTurntable();
  clearTimeout(state.timer);
  state.timer = setTimeout(show, 250);
}

function turnTo(azimuth) {
  state.azimuth = (azimuth + 360) % 360;
  byId("angle").textContent = angleName(state.azimuth);
  show();
}

// ---- Size advice: the advised sizes as pictures of the shopper's body ------------------------

// The advice's pictures are of the body the advice was for: another body or sex clears them.
function clearAdvice() {
  byId("advice").textContent = "";
  byId("advice-sizes").textContent = "";
  byId("ease-legend").hidden = true;
}

// The render of the shopper's body in `style` alone, in `size`, coloured by its ease. Standing
// at rest as the advice drapes it (a posed body cannot wear every style: sitting, a skirt).
function advicePictureUrl(style, size) {
  const p = bodyParameters(false);
  const row = worn().find((g) => g.style === style);
  p.set("outfit", style + ":" + size + ":" + (row ? row.colour : styleNamed(style).defaultColour));
  p.set("fitmap", "ease");
  p.set("view", "0," + ELEVATION);
  p.set("size", "240x320");
  return "/api/render?" + p.toString();
}

// One advised size: its picture, its name ("Recommended" on the advice's), its regions' text,
// and a button that puts it on the main picture.
function sizeCard(style, size, fit, recommended) {
  const card = element("li", "advice-size" + (recommended ? " recommended" : ""));
  card.dataset.size = size;
  const figure = element("figure");
  const img = element("img");
  img.width = 240;
  img.height = 320;
  img.alt = "Your " + bodyWords() + ", in the " + style + " in size " + size + ", its fit map: red on the skin, blue off it";
  img.src = advicePictureUrl(style, size);
  img.addEventListener("error", () => card.appendChild(element("p", "error", "This picture could not be drawn.")));
  const caption = element("figcaption");
  caption.appendChild(element("strong", "size-name", size));
  if (recommended) caption.appendChild(element("span", "badge", "Recommended"));
  // One line per region ("tight at the hips: 2 cm too little ease; loose at the waist: ...").
  for (const line of fit.text.split("; ")) caption.appendChild(element("span", "fit-text", line));
  figure.append(img, caption);
  const choose = element("button", "choose", "Wear " + size);
  choose.type = "button";
  choose.setAttribute("aria-label", "Wear the " + style + " in " + size + " in the main picture");
  choose.addEventListener("click", () => chooseSize(style, size));
  card.append(figure, choose);
  return card;
}

// Puts `size` on the main picture's garment of `style`; where none is worn, the outfit
// becomes that garment alone (what the advice pictured).
function chooseSize(style, size) {
  let row = worn().find((g) => g.style === style);
  if (!row) {
    for (let i = 1; byId("style-" + i); i++) {
      byId("style-" + i).value = "";
      fillSizes(byId("size-" + i), null);
    }
    wearStyle(0, style);
    row = { row: 0 };
  }
  byId("size-" + row.row).value = size;
  for (const card of byId("advice-sizes").children) card.classList.toggle("chosen", card.dataset.size === size);
  stopTurntable();
  clearTimeout(state.timer);
  show();
}

async function advise() {
  const problem = missingMeasure();
  if (problem) { byId("advice").textContent = problem; return; }
  const style = byId("fit-style").value;
  const p = bodyParameters(false);
  p.delete("skin");
  p.delete("light");
  p.set("style", style);
  clearAdvice();
  byId("advice").textContent = "Trying the sizes on…";
  const response = await fetch("/api/fit?" + p.toString());
  if (!response.ok) { byId("advice").textContent = await errorOf(response); return; }
  const body = await response.json();
  byId("advice").textContent = "Recommended: " + body.recommended +
      (body.all_tight ? " (every size is tight somewhere)" : "") + ". Each size on your body:";
  for (const [size, fit] of Object.entries(body.sizes))
    byId("advice-sizes").appendChild(sizeCard(style, size, fit, size === body.recommended));
  byId("ease-legend").hidden = false;
}

// ---- Turntable: 12 views as render jobs ------------------------------------------------------

// Posts one render job; its status URL. A full queue (503) or a client past its rate (429)
// is asked again after Retry-After: the same parameters are the same job.
async function postJob(parameters, ticket) {
  for (;;) {
    const response = await fetch("/api/render", { method: "POST", body: new URLSearchParams(parameters) });
    if (response.status === 202) return response.headers.get("Location");
    if ((response.status !== 503 && response.status !== 429) || ticket !== state.turntable)
      throw new Error(await errorOf(response));
    await sleep(1000 * Number(response.headers.get("Retry-After") || 2));
  }
}

// Polls a job until it ends; the URL of its picture (a cache hit once done).
async function jobResult(location, ticket) {
  for (;;) {
    const response = await fetch(location);
    if (!response.ok) throw new Error(await errorOf(response));
    const job = await response.json();
    if (job.status === "done") return job.result;
    if (job.status === "failed") throw new Error(errorWords(422, { error: job.error || "the render failed" }));
    if (ticket !== state.turntable) throw new Error("stopped");
    await sleep(400);
  }
}

function turntableProgress() {
  const frames = [...byId("turntable-frames").querySelectorAll("img")];
  const ready = frames.filter((img) => img.dataset.loaded === "yes").length;
  byId("turntable-status").textContent = ready === TURNTABLE_VIEWS
      ? "All " + TURNTABLE_VIEWS + " views are ready: choose one to see it large."
      : "Turning: " + ready + " of " + TURNTABLE_VIEWS + " views ready…";
}

// One view's frame: a button (the main picture turns to it) holding its picture once made.
function turntableFrame(azimuth, ticket) {
  const item = element("li");
  const button = element("button", "frame");
  button.type = "button";
  button.setAttribute("aria-label", "See the view from " + viewWords(azimuth));
  button.addEventListener("click", () => turnTo(azimuth));
  const img = element("img");
  img.width = 120;
  img.height = 160;
  img.alt = "Your " + bodyWords() + ", in " + outfitWords() + ", seen from " + viewWords(azimuth);
  img.dataset.view = azimuth + "," + ELEVATION;
  img.addEventListener("load", () => { img.dataset.loaded = "yes"; if (ticket === state.turntable) turntableProgress(); });
  img.addEventListener("error", () => {
    if (ticket === state.turntable) byId("turntable-status").textContent = "The view from " + viewWords(azimuth) + " could not be shown.";
  });
  button.appendChild(img);
  item.appendChild(button);
  return { item, img };
}

function stopTurntable() {
  state.turntable++;
  byId("turntable-frames").textContent = "";
  byId("turntable-status").textContent = "";
}

async function turntable() {
  const problem = missingMeasure();
  if (problem) { byId("turntable-status").textContent = problem; return; }
  stopTurntable();
  const ticket = state.turntable;
  turntableProgress();
  const views = [];
  for (let k = 0; k < TURNTABLE_VIEWS; k++) views.push((k * 360) / TURNTABLE_VIEWS);
  await Promise.all(views.map(async (azimuth) => {
    const frame = turntableFrame(azimuth, ticket);
    byId("turntable-frames").appendChild(frame.item);
    try {
      const result = await jobResult(await postJob(query(azimuth), ticket), ticket);
      if (ticket === state.turntable) frame.img.src = result;
    } catch (error) {
      if (ticket === state.turntable) byId("turntable-status").textContent = error.message;
    }
  }));
}

// ---- Start -----------------------------------------------------------------------------------

// The measurements' ranges and defaults of the chosen sex; `reset`: its defaults typed in.
function fillMeasures(reset) {
  byId("bust-name").textContent = sex() === "male" ? "Chest" : "Bust";
  for (const m of measures) {
    const range = state.catalogue.made.measurements[sex()][m];
    const input = byId(m);
    input.min = Math.ceil(range.min * 100);
    input.max = Math.floor(range.max * 100);
    if (reset) input.value = Math.round(range.default * 100);
  }
}

// The advice's garment follows the main garment unless the shopper chose another.
function fillFitStyles() {
  const before = byId("fit-style").value;
  byId("fit-style").textContent = "";
  madeStyles().forEach((s) => option(byId("fit-style"), s.name));
  byId("fit-style").value = styleNamed(before) ? before : byId("style-0").value || madeStyles()[0].name;
}

// Another sex: its ranges and defaults, its styles and sizes, its first style worn.
function changeSex() {
  fillMeasures(true);
  for (let i = 0; byId("style-" + i); i++) fillGarment(i);
  if (!byId("style-0").value && madeStyles().length) wearStyle(0, madeStyles()[0].name);
  fillFitStyles();
  clearAdvice();
  schedule();
}

async function start() {
  const catalogue = await (await fetch("/api/catalogue")).json();
  state.catalogue = catalogue;
  fillMeasures(true);
  for (const m of measures) byId(m).addEventListener("change", () => { clearAdvice(); schedule(); });
  catalogue.skinTones.forEach((t) => option(byId("skin"), t.name));
  byId("skin").value = "medium";
  catalogue.made.poses.forEach((p) => option(byId("pose"), p));
  catalogue.lights.forEach((l) => option(byId("light"), l));
  for (const k of ["skin", "pose", "light", "underwear"]) byId(k).addEventListener("change", schedule);
  for (let i = 0; i < catalogue.limits.garments; i++) {
    byId("garments").appendChild(garmentRow(i));
    fillGarment(i);
  }
  wearStyle(0, "dress");
  fillFitStyles();
  byId("sex").addEventListener("change", changeSex);
  byId("advise").addEventListener("click", advise);
  byId("turntable").addEventListener("click", turntable);
  byId("fitmap").addEventListener("change", () => {
    byId("fitmap-legend").hidden = !byId("fitmap").checked;
    stopTurntable();
    show();
  });
  byId("turn-left").addEventListener("click", () => turnTo(state.azimuth - 30));
  byId("turn-right").addEventListener("click", () => turnTo(state.azimuth + 30));
  show();
}

start();
