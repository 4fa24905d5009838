// The shopper's page: choices -> GET /api/render's parameters -> the picture of the
// shopper's own body (the made body, women's or men's) in the catalogue's garments, each in
// a size of the chart. Measurements are typed in cm and sent in metres; the catalogue (GET
// /api/catalogue, its "made" part) fills the lists for the chosen sex.
// "Fit map" draws the garments coloured by their stretch (fitmap=stretch: same drape).
// "Advise my size" asks GET /api/fit for the same measurements (only when pressed: a fit
// drapes three sizes, seconds) and lists the recommendation and each size's text.
"use strict";

const state = { azimuth: 0, catalogue: null, timer: null };
const sex = () => byId("sex").value;
const madeStyles = () => state.catalogue.made.styles.filter((s) => s.sizes[sex()]);
const byId = (id) => document.getElementById(id);
const measures = ["stature", "bust", "waist", "hips"];

function option(select, value, text) {
  const o = document.createElement("option");
  o.value = value;
  o.textContent = text || value;
  select.appendChild(o);
}

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
  style.value = madeStyles().some((s) => s.name === before) ? before : "";
  fillSizes(byId("size-" + index), madeStyles().find((s) => s.name === style.value));
}

function garmentRow(index) {
  const row = document.createElement("div");
  row.className = "garment";
  const style = document.createElement("select");
  style.id = "style-" + index;
  style.setAttribute("aria-label", "Garment " + (index + 1));
  const size = document.createElement("select");
  size.id = "size-" + index;
  size.setAttribute("aria-label", "Size of garment " + (index + 1));
  const colour = document.createElement("input");
  colour.type = "color";
  colour.id = "colour-" + index;
  colour.setAttribute("aria-label", "Colour of garment " + (index + 1));
  style.addEventListener("change", () => {
    const s = madeStyles().find((x) => x.name === style.value);
    if (s) colour.value = "#" + s.defaultColour;
    fillSizes(size, s);
  });
  [style, size, colour].forEach((e) => { row.appendChild(e); e.addEventListener("change", schedule); });
  return row;
}

function outfit() {
  const items = [];
  for (let i = 0; byId("style-" + i); i++) {
    const style = byId("style-" + i).value;
    if (style) items.push(style + ":" + byId("size-" + i).value + ":" + byId("colour-" + i).value.slice(1));
  }
  return items.length ? items.join(",") : "none";
}

function query() {
  const p = new URLSearchParams();
  p.set("sex", sex());
  for (const m of measures) p.set(m, (Number(byId(m).value) / 100).toFixed(3));
  for (const k of ["skin", "pose", "light"]) p.set(k, byId(k).value);
  p.set("outfit", outfit());
  if (byId("fitmap").checked) p.set("fitmap", "stretch");
  p.set("view", state.azimuth + ",5");
  p.set("size", "480x640");
  return p.toString();
}

async function show() {
  const url = "/api/render?" + query();
  byId("status").textContent = "Draping…";
  byId("error").textContent = "";
  const response = await fetch(url);
  if (!response.ok) {
    const body = await response.json().catch(() => ({ error: response.statusText }));
    byId("error").textContent = body.parameter
      ? body.parameter + ": " + body.error + " (accepted: " + body.accepted + ")"
      : body.error;
    byId("status").textContent = "";
    return;
  }
  const blob = await response.blob();
  const img = byId("picture");
  if (img.dataset.url) URL.revokeObjectURL(img.dataset.url);
  img.dataset.url = URL.createObjectURL(blob);
  img.dataset.query = url;
  byId("glb").href = url + "&format=glb";
  img.src = img.dataset.url;
  byId("status").textContent = "Shown (" + (response.headers.get("X-Figment-Cache") || "") + ")";
}

function adviceLine(text) {
  const p = document.createElement("p");
  p.textContent = text;
  byId("advice").appendChild(p);
}

async function advise() {
  const p = new URLSearchParams();
  p.set("sex", sex());
  p.set("style", byId("fit-style").value);
  for (const m of measures) p.set(m, (Number(byId(m).value) / 100).toFixed(3));
  byId("advice").textContent = "Trying the sizes on…";
  const response = await fetch("/api/fit?" + p.toString());
  const body = await response.json().catch(() => ({ error: response.statusText }));
  byId("advice").textContent = "";
  if (!response.ok) {
    adviceLine(body.parameter ? body.parameter + ": " + body.error + " (accepted: " + body.accepted + ")" : body.error);
    return;
  }
  adviceLine("Recommended: " + body.recommended + (body.all_tight ? " (every size is tight somewhere)" : ""));
  for (const [size, fit] of Object.entries(body.sizes)) adviceLine(size + ": " + fit.text);
}

function schedule() {
  clearTimeout(state.timer);
  state.timer = setTimeout(show, 250);
}

function turn(step) {
  state.azimuth = (state.azimuth + step + 360) % 360;
  const names = { 0: "front", 90: "right", 180: "back", 270: "left" };
  byId("angle").textContent = names[state.azimuth] || state.azimuth + "°";
  show();
}

// The measurements' ranges and defaults of the chosen sex; `reset`: its defaults typed in.
function fillMeasures(reset) {
  for (const m of measures) {
    const range = state.catalogue.made.measurements[sex()][m];
    const input = byId(m);
    input.min = Math.ceil(range.min * 100);
    input.max = Math.floor(range.max * 100);
    if (reset) input.value = Math.round(range.default * 100);
  }
}

// Another sex: its ranges and defaults, its styles and sizes, its first style worn.
function changeSex() {
  fillMeasures(true);
  for (let i = 0; byId("style-" + i); i++) fillGarment(i);
  if (!byId("style-0").value && madeStyles().length) {
    byId("style-0").value = madeStyles()[0].name;
    byId("colour-0").value = "#" + madeStyles()[0].defaultColour;
    fillSizes(byId("size-0"), madeStyles()[0]);
  }
  byId("fit-style").textContent = "";
  madeStyles().forEach((s) => option(byId("fit-style"), s.name));
  show();
}

async function start() {
  const catalogue = await (await fetch("/api/catalogue")).json();
  state.catalogue = catalogue;
  fillMeasures(true);
  for (const m of measures) byId(m).addEventListener("change", schedule);
  catalogue.skinTones.forEach((t) => option(byId("skin"), t.name));
  byId("skin").value = "medium";
  catalogue.made.poses.forEach((p) => option(byId("pose"), p));
  catalogue.lights.forEach((l) => option(byId("light"), l));
  for (const k of ["skin", "pose", "light"]) byId(k).addEventListener("change", schedule);
  for (let i = 0; i < catalogue.limits.garments; i++) {
    byId("garments").appendChild(garmentRow(i));
    fillGarment(i);
  }
  byId("style-0").value = "dress";
  byId("colour-0").value = "#" + madeStyles().find((s) => s.name === "dress").defaultColour;
  fillSizes(byId("size-0"), madeStyles().find((s) => s.name === "dress"));
  madeStyles().forEach((s) => option(byId("fit-style"), s.name));
  byId("sex").addEventListener("change", changeSex);
  byId("advise").addEventListener("click", advise);
  byId("fitmap").addEventListener("change", () => {
    byId("fitmap-legend").hidden = !byId("fitmap").checked;
    show();
  });
  byId("turn-left").addEventListener("click", () => turn(-30));
  byId("turn-right").addEventListener("click", () => turn(30));
  show();
}

start();
