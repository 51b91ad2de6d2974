// The trainer's page: plain HTML, SVG and a canvas, its script inline; it
// reads GET /state once (the trail so far, the robot's figures) and then
// GET /events, and draws each object it gets at the browser's next frame.
// From `trainer --session`, GET /replay answers, and the page is a session's
// replay instead (its own section of the script: play, pause, speed, the
// slider, the state lane; each time shown asked of GET /motion). The drawn
// vehicle's pose is kept on its element (data-x, data-y, data-heading,
// data-tick, data-time and data-t-ms: the object's own) for the browser
// tests (tests/trainer/).
#include "andros/trainer/trainer_page.hpp"

namespace andros::trainer {
namespace {

constexpr std::string_view kPage = R"page(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>andros-bridge trainer</title>
<style>
*{box-sizing:border-box}
body{margin:0;font:14px/1.3 "DejaVu Sans",sans-serif;background:#1d2125;color:#e8e8e8}
header{display:flex;gap:16px;align-items:center;padding:6px 12px;background:#2b3035;border-bottom:2px solid #444}
header h1{font-size:16px;margin:0;letter-spacing:.05em}
#state{font-weight:bold;padding:3px 10px;border-radius:3px;background:#7a1f1f;max-width:640px;white-space:nowrap;overflow:hidden;text-overflow:ellipsis}
#state.enabled{background:#1f6b2c}
#state.stopped{background:#b01515}
#state.ended{background:#555}
#link{margin-left:auto;color:#aaa}
main{display:grid;grid-template-columns:400px 1fr 320px;grid-template-rows:55fr 45fr;gap:8px;padding:8px;height:calc(100vh - 40px)}
section{background:#262b30;border:1px solid #3a4047;border-radius:4px;padding:6px;position:relative;min-height:0;overflow:hidden}
section h2{font-size:12px;margin:0 0 4px;color:#9fb3c8;text-transform:uppercase;letter-spacing:.08em}
#top{grid-row:1/3}
#top svg{width:100%;height:calc(100% - 20px);background:#39402f}
#side svg{width:100%;height:calc(100% - 20px);background:#2f3a44}
#camera{grid-column:2/3;grid-row:1/2}
#cam{width:100%;height:calc(100% - 20px);display:block;background:#000}
#inset{position:absolute;right:12px;bottom:12px;width:36%;border:2px solid #ddd;background:#000}
.label{position:absolute;left:12px;top:28px;background:rgba(0,0,0,.55);padding:2px 6px;font-weight:bold}
.insetlabel{position:absolute;right:14px;bottom:calc(12px + 27%);background:rgba(0,0,0,.55);padding:1px 5px;font-size:12px}
#panel{grid-column:3/4;grid-row:1/3;overflow:auto}
table{border-collapse:collapse;width:100%}
td{padding:0 4px;border-bottom:1px solid #333;font-size:13px}
td:first-child{color:#9fb3c8;width:45%}
.bar{height:8px;background:#555;position:relative;border-radius:2px}
.bar i{position:absolute;top:0;bottom:0;background:#7fb2e5;left:50%}
.held{display:inline-block;padding:1px 6px;margin:1px;background:#d9a21b;color:#000;border-radius:3px;font-weight:bold}
.fired{display:inline-block;padding:1px 6px;margin:1px;border-radius:3px;background:#444}
.fired.now{background:#e03131;color:#fff}
.on{color:#ff6b6b;font-weight:bold}
/* A session's replay (--session): the controls and the state lane under the views. */
#replay{display:none;align-items:center;gap:10px;padding:4px 12px;background:#2b3035;border-top:2px solid #444}
body.replay #replay{display:flex}
body.replay main{height:calc(100vh - 40px - 58px)}
#replay button{width:70px;font-weight:bold}
#replay .track{flex:1;display:flex;flex-direction:column;gap:2px}
#slider{width:100%;margin:0}
#lane{width:100%;height:14px;display:block;background:#444}
#rnote{color:#ffb74d;max-width:360px;white-space:nowrap;overflow:hidden;text-overflow:ellipsis}
#coursebox{margin-bottom:8px;padding:4px;border:1px solid #556;border-radius:3px}
#score div{font-size:13px}
#score .result{font-weight:bold}
#score .done{color:#6fdc7d}
#score .warn{color:#ffb347;font-weight:bold}
#score .bad{color:#ff6b6b;font-weight:bold}
</style></head>
<body>
<header><h1>andros-bridge TRAINER</h1><span id="robot">simulated vehicle</span>
<span id="state">waiting for the first frame</span><span id="link">connecting</span></header>
<main>
<section id="top"><h2>Top view (x east, y north; REP 103)</h2>
<svg id="topsvg" viewBox="0 0 420 640" preserveAspectRatio="xMidYMid meet">
<g id="grid"></g><g id="course"></g><polyline id="trail" fill="none" stroke="#ffd75e" stroke-width="2" points=""/>
<g id="vehicle" data-x="0" data-y="0" data-heading="0" data-tick="-1" data-time="-1">
<rect id="body" fill="#c8ccd0" stroke="#222"/><path id="nose" fill="#e03131"/><line id="armtop" stroke="#2f7de1" stroke-width="4"/>
</g>
<g id="scale"><line x1="16" y1="620" x2="16" y2="620" stroke="#fff" stroke-width="3"/><text x="16" y="612" fill="#fff" font-size="13"></text></g>
<text id="poseText" x="10" y="20" fill="#fff" font-size="14"></text>
</svg></section>
<section id="camera"><h2>Main camera</h2><canvas id="cam" width="640" height="300"></canvas>
<span class="label" id="camlabel">front drive</span>
<canvas id="inset" width="230" height="108"></canvas><span class="insetlabel" id="insetlabel">inset: none</span></section>
<section id="side"><h2>Side view (left side): flippers, arm, gripper</h2>
<svg id="sidesvg" viewBox="-1.9 -2.75 4.6 2.95" preserveAspectRatio="xMidYMid meet">
<line x1="-1.9" y1="0" x2="2.7" y2="0" stroke="#777" stroke-width="0.01"/>
<g id="sidebody"></g></svg></section>
<section id="panel"><div id="coursebox" hidden><h2>Course</h2><div id="score"></div></div>
<h2>Operating state</h2><div id="words">-</div>
<h2 style="margin-top:8px">Pad inputs</h2><div id="pad">-</div><table id="axes"></table>
<h2 style="margin-top:8px">Fired</h2><div id="weapons"></div><div id="laser"></div>
<h2 style="margin-top:8px">Vehicle</h2><table id="facts"></table></section>
</main>
<footer id="replay"><button id="play" type="button">play</button>
<label>speed <select id="speed"><option>0.25</option><option>0.5</option><option selected>1</option>
<option>2</option><option>4</option><option>8</option></select>x</label>
<div class="track"><input id="slider" type="range" min="0" max="0" step="1" value="0" aria-label="time in the session">
<svg id="lane" preserveAspectRatio="none"></svg></div>
<span id="rtime" data-t-ms="0">0.00 / 0.00 s</span><span id="rnote"></span></footer>
<script>
"use strict";
const $ = id => document.getElementById(id);
const NS = "http://www.w3.org/2000/svg";
let fig = {length:1.209,width:0.66,height:0.635,upper_arm:0.75,forearm:0.7,flipper:0.45};
let trail = [];
let latest = null, drawn = null, lastFired = {}, firedAt = {};
const PX = 26;  // top view: pixels per metre
const LANDMARKS = [[5,0],[10,2.5],[10,-2.5],[15,0],[0,5],[0,-5],[-5,0],[5,5],[5,-5]];
const rad = d => d * Math.PI / 180;
function el(tag, attrs, parent) {
  const e = document.createElementNS(NS, tag);
  for (const k in attrs) e.setAttribute(k, attrs[k]);
  if (parent) parent.appendChild(e);
  return e;
}
function text(id, t) { const e = $(id); if (e.textContent !== t) e.textContent = t; }
function addTrail(x, y) {
  const last = trail[trail.length - 1];
  if (!last || Math.hypot(x - last[0], y - last[1]) >= 0.05) trail.push([x, y]);
  if (trail.length > 20000) trail.shift();
}
function drawTop(s) {
  const svg = $("topsvg"), W = 420, H = 640;
  const cx = s.pose.x, cy = s.pose.y;
  const sx = x => W / 2 + (x - cx) * PX, sy = y => H / 2 - (y - cy) * PX;
  const g = $("grid"); g.textContent = "";
  const x0 = Math.floor(cx - W / 2 / PX), x1 = Math.ceil(cx + W / 2 / PX);
  const y0 = Math.floor(cy - H / 2 / PX), y1 = Math.ceil(cy + H / 2 / PX);
  for (let x = x0; x <= x1; x++) el("line", {x1:sx(x),y1:0,x2:sx(x),y2:H,stroke:x===0?"#9aa":"#4b5540","stroke-width":x%5===0?1.5:0.7}, g);
  for (let y = y0; y <= y1; y++) el("line", {x1:0,y1:sy(y),x2:W,y2:sy(y),stroke:y===0?"#9aa":"#4b5540","stroke-width":y%5===0?1.5:0.7}, g);
  if (!courseMap) for (const [lx, ly] of LANDMARKS) el("circle", {cx:sx(lx),cy:sy(ly),r:5,fill:"#ff8c1a",stroke:"#000"}, g);
  el("circle", {cx:sx(0),cy:sy(0),r:4,fill:"none",stroke:"#fff"}, g);
  drawCourse(s, sx, sy);
  $("trail").setAttribute("points", trail.map(p => sx(p[0]).toFixed(1) + "," + sy(p[1]).toFixed(1)).join(" "));
  const L = fig.length * PX, Wd = fig.width * PX;
  const b = $("body");
  b.setAttribute("x", -L / 2); b.setAttribute("y", -Wd / 2); b.setAttribute("width", L); b.setAttribute("height", Wd);
  $("nose").setAttribute("d", `M${L/2},0 L${L/2-10},-7 L${L/2-10},7 Z`);
  const reach = (Math.cos(rad(s.arm.shoulder)) * fig.upper_arm + 0.3) * PX;
  const ta = $("armtop");
  ta.setAttribute("x1", 0); ta.setAttribute("y1", 0);
  ta.setAttribute("x2", Math.cos(rad(s.arm.torso)) * reach); ta.setAttribute("y2", -Math.sin(rad(s.arm.torso)) * reach);
  const v = $("vehicle");
  v.setAttribute("transform", `translate(${sx(s.pose.x)},${sy(s.pose.y)}) rotate(${-s.pose.heading})`);
  v.dataset.x = s.pose.x; v.dataset.y = s.pose.y; v.dataset.heading = s.pose.heading; v.dataset.tick = s.tick; v.dataset.time = s.time; v.dataset.tMs = s.t_ms;
  const line = $("scale").firstElementChild;
  line.setAttribute("x2", 16 + 5 * PX);
  $("scale").lastElementChild.textContent = "5 m";
  text("poseText", `x ${s.pose.x.toFixed(2)} m  y ${s.pose.y.toFixed(2)} m  heading ${s.pose.heading.toFixed(1)}\u00b0`);
}
// The arm in the torso's plane: each point as [forward, up] from the shoulder, in metres.
function armPoints(s) {
  const a1 = rad(s.arm.shoulder), a2 = a1 + rad(180 - s.arm.elbow), a3 = a2 + rad(s.arm.wrist);
  const sh = [fig.length * 0.15, fig.height];
  const el_ = [sh[0] + fig.upper_arm * Math.cos(a1), sh[1] + fig.upper_arm * Math.sin(a1)];
  const wr = [el_[0] + fig.forearm * Math.cos(a2), el_[1] + fig.forearm * Math.sin(a2)];
  const g = 0.22 + s.arm.wrist_extension;
  const tip = [wr[0] + g * Math.cos(a3), wr[1] + g * Math.sin(a3)];
  return {sh, el: el_, wr, tip, a3};
}
function drawSide(s) {
  const g = $("sidebody"); g.textContent = "";
  const L = fig.length, H = fig.height, c = Math.cos(rad(s.arm.torso));
  const P = (x, z) => `${x.toFixed(3)},${(-z).toFixed(3)}`;
  el("rect", {x:-L/2,y:-0.3,width:L,height:0.3,rx:0.15,fill:"#333",stroke:"#111","stroke-width":0.01}, g);
  el("rect", {x:-L/2+0.08,y:-H,width:L-0.16,height:H-0.25,fill:"#c8ccd0",stroke:"#222","stroke-width":0.01}, g);
  const ff = rad(s.flippers.front), rf = rad(s.flippers.rear);
  el("line", {x1:L/2,y1:-0.15,x2:L/2+fig.flipper*Math.cos(ff),y2:-0.15-fig.flipper*Math.sin(ff),stroke:"#f0a500","stroke-width":0.09,"stroke-linecap":"round"}, g);
  el("line", {x1:-L/2,y1:-0.15,x2:-L/2-fig.flipper*Math.cos(rf),y2:-0.15-fig.flipper*Math.sin(rf),stroke:"#f0a500","stroke-width":0.09,"stroke-linecap":"round"}, g);
  const m = s.cameras.extender;
  el("line", {x1:-L/4,y1:-H,x2:-L/4,y2:-(H+0.15+m),stroke:"#888","stroke-width":0.04}, g);
  el("rect", {x:-L/4-0.07,y:-(H+0.25+m),width:0.14,height:0.1,fill:"#222",stroke:"#aaa","stroke-width":0.01,transform:`rotate(${-s.cameras.tilt} ${-L/4} ${-(H+0.2+m)})`}, g);
  const a = armPoints(s);
  const X = p => p[0] * c;  // the torso turned: the arm seen foreshortened
  el("polyline", {points:[a.sh,a.el,a.wr].map(p => P(X(p), p[1])).join(" "),fill:"none",stroke:"#2f7de1","stroke-width":0.07,"stroke-linejoin":"round","stroke-linecap":"round"}, g);
  el("line", {x1:X(a.wr),y1:-a.wr[1],x2:X(a.tip),y2:-a.tip[1],stroke:"#8fb8ff","stroke-width":0.04}, g);
  const o = 0.02 + 0.08 * s.gripper.opening, n = [-Math.sin(a.a3), Math.cos(a.a3)];
  for (const sgn of [1, -1]) {
    el("line", {x1:X(a.tip),y1:-a.tip[1],x2:X([a.tip[0]+0.12*Math.cos(a.a3)+sgn*o*n[0]]),y2:-(a.tip[1]+0.12*Math.sin(a.a3)+sgn*o*n[1]),stroke:"#ffd75e","stroke-width":0.03}, g);
  }
  for (const p of [a.sh, a.el, a.wr]) el("circle", {cx:X(p),cy:-p[1],r:0.04,fill:"#fff"}, g);
}
// A camera's eye in the world: position [x, y, z], yaw and pitch in degrees.
function cameraEye(s, which) {
  const h = rad(s.pose.heading), L = fig.length, H = fig.height;
  const at = (fx, fy, z) => [s.pose.x + fx * Math.cos(h) - fy * Math.sin(h), s.pose.y + fx * Math.sin(h) + fy * Math.cos(h), z];
  if (which === "rear drive") return {p: at(-L / 2, 0, 0.3), yaw: s.pose.heading + 180, pitch: -6, zoom: 1};
  if (which === "PTZ") return {p: at(-L / 4, 0, H + 0.2 + s.cameras.extender), yaw: s.pose.heading + s.cameras.pan, pitch: s.cameras.tilt, zoom: s.cameras.zoom};
  if (which === "gripper") {
    const a = armPoints(s), t = rad(s.arm.torso);
    const d = [Math.cos(a.a3) * Math.cos(t), Math.cos(a.a3) * Math.sin(t), Math.sin(a.a3)];
    const p = at(a.wr[0] * Math.cos(t), a.wr[0] * Math.sin(t), a.wr[1]);
    return {p, yaw: s.pose.heading + Math.atan2(d[1], d[0]) * 180 / Math.PI, pitch: Math.asin(Math.max(-1, Math.min(1, d[2]))) * 180 / Math.PI, zoom: 1, gripper: true};
  }
  return {p: at(L / 2, 0, 0.3), yaw: s.pose.heading, pitch: -6, zoom: 1};
}
function drawCamera(canvas, s, which) {
  const ctx = canvas.getContext("2d"), W = canvas.width, Hh = canvas.height;
  if (which === "none") { ctx.fillStyle = "#111"; ctx.fillRect(0, 0, W, Hh); return; }
  const e = onCourse(s, cameraEye(s, which)), y = rad(e.yaw), p = rad(e.pitch);
  const f = [Math.cos(y) * Math.cos(p), Math.sin(y) * Math.cos(p), Math.sin(p)];
  const r = [Math.sin(y), -Math.cos(y), 0];
  const u = [-Math.cos(y) * Math.sin(p), -Math.sin(y) * Math.sin(p), Math.cos(p)];
  const focal = (W / 2) / Math.tan(rad(30) / e.zoom);
  const proj = q => {
    const d = [q[0] - e.p[0], q[1] - e.p[1], q[2] - e.p[2]];
    const zc = d[0] * f[0] + d[1] * f[1] + d[2] * f[2];
    if (zc < 0.05) return null;
    return [W / 2 + focal * (d[0] * r[0] + d[1] * r[1]) / zc, Hh / 2 - focal * (d[0] * u[0] + d[1] * u[1] + d[2] * u[2]) / zc];
  };
  const lum = 0.55 + 0.45 * s.light;
  ctx.fillStyle = `rgb(${90*lum|0},${130*lum|0},${170*lum|0})`; ctx.fillRect(0, 0, W, Hh);
  const horizon = Hh / 2 + focal * Math.tan(p);
  ctx.fillStyle = `rgb(${70*lum|0},${82*lum|0},${55*lum|0})`; ctx.fillRect(0, Math.max(0, horizon), W, Hh);
  const seg = (a, b, color, width) => {
    const A = proj(a), B = proj(b); if (!A || !B) return;
    ctx.strokeStyle = color; ctx.lineWidth = width; ctx.beginPath(); ctx.moveTo(A[0], A[1]); ctx.lineTo(B[0], B[1]); ctx.stroke();
  };
  const gx = Math.round(e.p[0]), gy = Math.round(e.p[1]);
  for (let i = -25; i <= 25; i++) for (let j = -25; j < 25; j++) {
    seg([gx + i, gy + j, 0], [gx + i, gy + j + 1, 0], (gx + i) === 0 ? "#bbb" : "#5b6648", 1);
    seg([gx + j, gy + i, 0], [gx + j + 1, gy + i, 0], (gy + i) === 0 ? "#bbb" : "#5b6648", 1);
  }
  for (let k = 1; k < trail.length; k++) seg([trail[k-1][0], trail[k-1][1], 0.01], [trail[k][0], trail[k][1], 0.01], "#ffd75e", 2);
  if (courseMap) drawCourseInCamera(s, seg);
  else for (const [lx, ly] of LANDMARKS) {
    const base = proj([lx, ly, 0]), top = proj([lx, ly, 0.5]);
    if (!base || !top) continue;
    const w = Math.max(2, (base[1] - top[1]) * 0.5);
    ctx.fillStyle = "#ff8c1a"; ctx.beginPath(); ctx.moveTo(top[0], top[1]); ctx.lineTo(base[0] - w, base[1]); ctx.lineTo(base[0] + w, base[1]); ctx.fill();
  }
  if (e.gripper) {  // the jaws, in the lower part of the picture
    const o = 20 + 90 * s.gripper.opening;
    ctx.fillStyle = "#777";
    ctx.save(); ctx.translate(W / 2, Hh); ctx.rotate(rad(s.gripper.rotation));
    ctx.fillRect(-o - 18, -Hh * 0.35, 18, Hh * 0.35); ctx.fillRect(o, -Hh * 0.35, 18, Hh * 0.35); ctx.restore();
  }
  if (s.laser) { ctx.fillStyle = "#ff2020"; ctx.beginPath(); ctx.arc(W / 2, Hh / 2, 4, 0, 7); ctx.fill(); }
}
function drawPanel(s) {
  const st = $("state");
  text("state", s.state || s.state_name);
  st.className = ["enabled", "stopped", "ended"].includes(s.state_name) ? s.state_name : "";
  text("robot", "simulated " + s.robot + (s.layer ? "  layer: " + s.layer : ""));
  text("words", s.state || "-");
  const pad = $("pad");
  const held = s.pad.buttons.map(b => `<span class="held">${b}</span>`).join("");
  const name = s.pad.connected ? s.pad.name : "no controller";
  pad.innerHTML = "";
  const n = document.createElement("div"); n.textContent = name; pad.appendChild(n);
  const h = document.createElement("div"); h.innerHTML = held || "<i>no button held</i>"; pad.appendChild(h);
  let rows = "";
  for (const k in s.pad.axes) {
    const v = s.pad.axes[k] / 32768, w = Math.abs(v) * 50;
    rows += `<tr><td>${k}</td><td><div class="bar"><i style="left:${v < 0 ? 50 - w : 50}%;width:${w}%"></i></div></td></tr>`;
  }
  $("axes").innerHTML = rows;
  const now = performance.now();
  let wh = "";
  for (const k in s.fired) {
    if (lastFired[k] !== undefined && s.fired[k] > lastFired[k]) firedAt[k] = now;
    lastFired[k] = s.fired[k];
    const recent = firedAt[k] && now - firedAt[k] < 1500;
    wh += `<span class="fired${recent ? " now" : ""}">${k}: ${s.fired[k]}</span>`;
  }
  $("weapons").innerHTML = wh;
  $("laser").innerHTML = s.laser ? '<span class="on">LASER ON</span>' : "laser off";
  const c = s.cameras, a = s.arm;
  const facts = [
    ["speed", `${s.speed.toFixed(2)} m/s`], ["turn", `${s.turn_rate.toFixed(1)} \u00b0/s`],
    ["drive allowed", s.drive ? "yes" : "no"], ["safety bit", s.safety ? "on" : "off"],
    ["flippers", `front ${s.flippers.front.toFixed(0)}\u00b0 rear ${s.flippers.rear.toFixed(0)}\u00b0`],
    ["torso / shoulder", `${a.torso.toFixed(0)}\u00b0 / ${a.shoulder.toFixed(0)}\u00b0`],
    ["elbow / wrist", `${a.elbow.toFixed(0)}\u00b0 / ${a.wrist.toFixed(0)}\u00b0`],
    ["wrist extension", `${a.wrist_extension.toFixed(2)} m`],
    ["gripper", `open ${(s.gripper.opening * 100).toFixed(0)}% rot ${s.gripper.rotation.toFixed(0)}\u00b0`],
    ["PTZ pan / tilt", `${c.pan.toFixed(0)}\u00b0 / ${c.tilt.toFixed(0)}\u00b0`],
    ["zoom / focus / iris", `${c.zoom.toFixed(1)}x / ${c.focus.toFixed(2)} / ${c.iris.toFixed(2)}`],
    ["extender", `${c.extender.toFixed(2)} m`], ["light", `${(s.light * 100).toFixed(0)}%`],
    ["tool", s.tool_on ? "on" : "off"], ["enable key", s.enable_key ? "on" : "off"],
    ["watchdog", s.watchdog ? "TRIPPED: stopped" : "fed"],
    ["frames / ignored", `${s.frames} / ${s.ignored}`], ["tick / time", `${s.tick} / ${s.time.toFixed(2)} s`]];
  $("facts").innerHTML = facts.map(f => `<tr><td>${f[0]}</td><td>${f[1]}</td></tr>`).join("");
  text("camlabel", "main: " + c.main);
  text("insetlabel", "inset: " + c.inset);
  $("inset").style.display = c.inset === "none" ? "none" : "block";
}
// --- The course (docs/trainer.md, "Courses"): its map in the top view, the score in the panel ---
let courseMap = null;
function corners(a, sx, sy) {
  const h = rad(a.heading), l = a.size[0] / 2, w = a.size[1] / 2;
  const c = Math.cos(h), n = Math.sin(h);
  return [[l, w], [l, -w], [-l, -w], [-l, w]].map(([u, v]) =>
    `${sx(a.at[0] + u * c - v * n).toFixed(1)},${sy(a.at[1] + u * n + v * c).toFixed(1)}`).join(" ");
}
function drawCourse(s, sx, sy) {
  const g = $("course"); g.textContent = "";
  if (!courseMap) return;
  const m = courseMap, cs = s.course || {};
  const poly = (a, attrs) => el("polygon", Object.assign({points: corners(a, sx, sy)}, attrs), g);
  const gx = m.ground.x, gy = m.ground.y;
  el("rect", {x: sx(gx[0]), y: sy(gy[1]), width: (gx[1] - gx[0]) * PX, height: (gy[1] - gy[0]) * PX,
              fill: "none", stroke: "#e8e8e8", "stroke-width": 2, "stroke-dasharray": "6 4"}, g);
  for (const l of m.landings) poly(l.area, {fill: "#5d6b7a", stroke: "#aab"});
  for (const sl of m.slopes) {
    poly(sl.area, {fill: sl.kind === "stairs" ? "#6d5a45" : "#6b6b4a", stroke: "#cc9"});
    const h = rad(sl.area.heading), L = sl.area.size[0] / 2;
    // Steps (or the ramp's fall line) across it, and its angle.
    for (let k = -4; k <= 4; k++) {
      const u = k * L / 5, W = sl.area.size[1] / 2;
      el("line", {x1: sx(sl.area.at[0] + u * Math.cos(h) - W * Math.sin(h)), y1: sy(sl.area.at[1] + u * Math.sin(h) + W * Math.cos(h)),
                  x2: sx(sl.area.at[0] + u * Math.cos(h) + W * Math.sin(h)), y2: sy(sl.area.at[1] + u * Math.sin(h) - W * Math.cos(h)),
                  stroke: "#000", "stroke-opacity": 0.35}, g);
    }
    const t = el("text", {x: sx(sl.area.at[0]), y: sy(sl.area.at[1]), fill: "#fff", "font-size": 12, "text-anchor": "middle"}, g);
    t.textContent = `${sl.kind} ${sl.angle}\u00b0 \u2191`;
  }
  if (m.finish) poly(m.finish, {fill: cs.in_finish ? "#2e7d32" : "none", stroke: "#6fdc7d", "stroke-width": 2, "stroke-dasharray": "4 3"});
  if (m.package && m.package.drop) poly(m.package.drop, {fill: cs.package && cs.package.delivered ? "#2e7d32" : "none", stroke: "#ffd75e", "stroke-width": 2, "stroke-dasharray": "4 3"});
  for (const b of m.blocks) poly(b.area, {fill: "#8d8f94", stroke: "#222"});
  m.gates.forEach((gt, i) => {
    const h = rad(gt.heading), W = gt.width / 2, passed = cs.gates > i, next = cs.gates === i;
    const ax = gt.at[0] - W * Math.sin(h), ay = gt.at[1] + W * Math.cos(h), bx = gt.at[0] + W * Math.sin(h), by = gt.at[1] - W * Math.cos(h);
    el("line", {x1: sx(ax), y1: sy(ay), x2: sx(bx), y2: sy(by), stroke: passed ? "#6fdc7d" : next ? "#ffd75e" : "#ccc",
                "stroke-width": 3, "stroke-dasharray": passed ? "" : "5 4"}, g);
    for (const [px, py] of [[ax, ay], [bx, by]]) el("circle", {cx: sx(px), cy: sy(py), r: 4, fill: "#e03131"}, g);
    const t = el("text", {x: sx(ax) + 6, y: sy(ay) - 4, fill: "#fff", "font-size": 13, "font-weight": "bold"}, g);
    t.textContent = String(i + 1);
  });
  if (m.door) {
    const h = rad(m.door.closed + (cs.door_angle || 0)), d = m.door;
    el("line", {x1: sx(d.hinge[0]), y1: sy(d.hinge[1]), x2: sx(d.hinge[0] + d.width * Math.cos(h)), y2: sy(d.hinge[1] + d.width * Math.sin(h)),
                stroke: "#4fc3f7", "stroke-width": 5}, g);
  }
  if (m.target) {
    el("circle", {cx: sx(m.target.at[0]), cy: sy(m.target.at[1]), r: Math.max(4, m.target.radius * PX), fill: "none",
                  stroke: cs.laser_on_target ? "#ff3b3b" : "#fff", "stroke-width": 3}, g);
    el("circle", {cx: sx(m.target.at[0]), cy: sy(m.target.at[1]), r: 3, fill: "#ff3b3b"}, g);
  }
  if (m.package && cs.package) {
    const p = cs.package, z = m.package.size * PX;
    el("rect", {x: sx(p.at[0]) - z / 2, y: sy(p.at[1]) - z / 2, width: z, height: z, fill: "#c98a2b", stroke: p.held ? "#fff" : "#000", "stroke-width": 2}, g);
  }
}
// The course in a camera's picture: each block, slope and landing as its edges, the door, the gates' posts, the target.
function drawCourseInCamera(s, seg) {
  const m = courseMap, cs = s.course || {};
  const box = (a, z0, z1, color) => {
    const h = rad(a.heading), c = Math.cos(h), n = Math.sin(h), l = a.size[0] / 2, w = a.size[1] / 2;
    const pts = [[l, w], [l, -w], [-l, -w], [-l, w]].map(([u, v]) => [a.at[0] + u * c - v * n, a.at[1] + u * n + v * c]);
    const lo = k => z0 instanceof Array ? z0[k] : z0, hi = k => z1 instanceof Array ? z1[k] : z1;
    for (let k = 0; k < 4; k++) {
      const p = pts[k], q = pts[(k + 1) % 4];
      seg([p[0], p[1], lo(k)], [q[0], q[1], lo((k + 1) % 4)], color, 2);
      seg([p[0], p[1], hi(k)], [q[0], q[1], hi((k + 1) % 4)], color, 2);
      seg([p[0], p[1], lo(k)], [p[0], p[1], hi(k)], color, 2);
    }
  };
  for (const b of m.blocks) box(b.area, 0, b.height, "#d0d2d6");
  for (const l of m.landings) box(l.area, 0, l.height, "#9fb3c8");
  for (const sl of m.slopes) {
    const rise = sl.area.size[0] * Math.tan(rad(sl.angle));
    box(sl.area, 0, [rise, rise, 0, 0], sl.kind === "stairs" ? "#d9a066" : "#c8c870");
  }
  if (m.door) {
    const h = rad(m.door.closed + (cs.door_angle || 0)), d = m.door, e = [d.hinge[0] + d.width * Math.cos(h), d.hinge[1] + d.width * Math.sin(h)];
    for (const z of [0, 1.4]) seg([d.hinge[0], d.hinge[1], z], [e[0], e[1], z], "#4fc3f7", 3);
    seg([e[0], e[1], 0], [e[0], e[1], 1.4], "#4fc3f7", 3);
  }
  for (const gt of m.gates) {
    const h = rad(gt.heading), W = gt.width / 2;
    for (const sgn of [-1, 1]) {
      const x = gt.at[0] + sgn * W * Math.sin(h), y = gt.at[1] - sgn * W * Math.cos(h);
      seg([x, y, 0], [x, y, 1.2], "#e03131", 4);
    }
  }
  if (m.target) {
    const t = m.target;
    for (let k = 0; k < 12; k++) {
      const a0 = k * Math.PI / 6, a1 = (k + 1) * Math.PI / 6, r = t.radius;
      seg([t.at[0], t.at[1] + r * Math.cos(a0), t.z + r * Math.sin(a0)], [t.at[0], t.at[1] + r * Math.cos(a1), t.z + r * Math.sin(a1)], cs.laser_on_target ? "#ff3b3b" : "#fff", 3);
    }
  }
  if (cs.package && m.package) {
    const p = cs.package, z = m.package.size;
    box({at: p.at, size: [z, z], heading: 0}, p.z, p.z + z, "#c98a2b");
  }
}
// A camera on the vehicle raised and pitched with it on a course's slopes and landings.
function onCourse(s, e) {
  if (!s.course) return e;
  e.p[2] += s.course.elevation;
  e.pitch += s.course.pitch * Math.cos(rad(e.yaw - s.pose.heading));
  return e;
}
// The side view pitched with the slope under the vehicle (nose up: counter-clockwise on the screen).
function drawPitch(s) {
  const pitch = s.course ? s.course.pitch : 0;
  $("sidebody").setAttribute("transform", pitch ? `rotate(${(-pitch).toFixed(2)})` : "");
}
function drawScore(s) {
  const box = $("coursebox");
  if (!courseMap) return;
  box.hidden = false;
  const sc = s.score, cs = s.course || {}, m = courseMap, out = $("score");
  out.textContent = "";
  const line = (t, cls) => { const d = document.createElement("div"); d.textContent = t; if (cls) d.className = cls; out.appendChild(d); };
  line(courseMap.name + (sc ? ": " + sc.result : ""), "result " + (sc && sc.completed ? "done" : ""));
  if (cs.tipped) line("TIPPED OVER: the run has failed", "bad");
  else if (cs.tip_warning) line(`TIPPING: ${cs.tip_margin.toFixed(2)} m from tipping over`, "warn");
  if (cs.elevation > 0.005 || Math.abs(cs.pitch) > 0.05) line(`height ${cs.elevation.toFixed(2)} m, pitch ${cs.pitch.toFixed(0)}\u00b0`);
  if (cs.climb_blocked) line("too steep, or stairs with the front flippers down: it will not climb", "warn");
  if (cs.touching) line("CONTACT: against a wall", "warn");
  if (!sc) return;
  line(`time ${sc.time_s.toFixed(1)} s` + (sc.time_limit_s > 0 ? ` of ${sc.time_limit_s} s` : "") +
       (sc.gates_total > 0 ? `   gates ${sc.gates}/${sc.gates_total}` : "") + `   contacts ${sc.contacts}`);
  line(`stops ${sc.stops.length}` + sc.stops.map(p => `; ${(p.t_ms / 1000).toFixed(1)} s ${p.by} (${p.why})`).join(""));
  line(`enabled with inputs not at rest: ${sc.not_at_rest}`);
  line(`fired ${sc.fired}: on target ${sc.hits}, laser off target ${sc.fired_off_target}, refused (no consent) ${sc.fire_refused}`);
  if (m.package && cs.package) line(`package: ${cs.package.delivered ? "delivered" : cs.package.held ? "held" : cs.package.lifted ? "set down" : "not lifted"}` +
                       (courseMap.door ? `   door ${cs.door_angle.toFixed(0)}\u00b0 open` : ""));
}
function draw() {
  requestAnimationFrame(draw);
  if (!latest || latest === drawn) return;
  drawn = latest;
  const s = latest;
  drawTop(s); drawSide(s); drawScore(s); drawPitch(s);
  drawCamera($("cam"), s, s.cameras.main);
  if (s.cameras.inset !== "none") drawCamera($("inset"), s, s.cameras.inset);
  drawPanel(s);
}
function take(s) {
  if (!s || s.pose === undefined) return;
  if (!replay.data) addTrail(s.pose.x, s.pose.y);
  latest = s;
}
function live() {
  fetch("/state").then(r => r.json()).then(s => {
    if (s.figures) fig = s.figures;
    if (s.course_map) courseMap = s.course_map;
    if (s.trail) trail = s.trail.slice();
    take(s);
    const es = new EventSource("/events");
    es.onopen = () => text("link", "live: /events");
    es.onerror = () => text("link", "stream lost: reconnecting");
    es.onmessage = m => take(JSON.parse(m.data));
  }).catch(() => text("link", "no answer from the trainer"));
}

// ---- A session's replay (trainer --session): play, pause, speed, seek, the state lane ----
// The server integrated the session once; the page asks for the object at a
// time (GET /motion?t=SECONDS), one request at a time, and shows the trail's
// points up to that time (GET /replay gave them all, with their times).
const replay = {data: null, playing: false, t: 0, shown: -1, asking: false, last: null};
function replayTrail(t) {
  const pts = replay.data.trail;
  let lo = 0, hi = pts.length;  // the points added at or before t
  while (lo < hi) { const mid = (lo + hi) >> 1; if (pts[mid][0] <= t) lo = mid + 1; else hi = mid; }
  trail = pts.slice(Math.max(0, lo - 20000), lo).map(p => [p[1], p[2]]);
}
function replayAsk() {
  if (replay.asking || replay.shown === replay.t) return;
  const t = replay.t;
  replay.asking = true;
  fetch("/motion?t=" + (t / 1000).toFixed(3)).then(r => r.json()).then(s => {
    replay.asking = false;
    replay.shown = t;
    replayTrail(t);
    take(s);
    const r = $("rtime");
    r.dataset.tMs = t;
    r.textContent = (t / 1000).toFixed(2) + " / " + (replay.data.length_ms / 1000).toFixed(2) + " s";
  }).catch(() => { replay.asking = false; text("link", "no answer from the trainer"); });
}
function replaySeek(t) {
  replay.t = Math.max(0, Math.min(replay.data.length_ms, Math.round(t)));
  $("slider").value = replay.t;
  replayAsk();
}
function replayPlay(on) {
  // At the end, play starts again from the beginning.
  if (on && replay.t >= replay.data.length_ms) replaySeek(0);
  replay.playing = on;
  replay.last = null;
  $("play").textContent = on ? "pause" : "play";
  $("play").dataset.playing = on;
}
function replayFrame(now) {
  requestAnimationFrame(replayFrame);
  if (replay.playing) {
    if (replay.last !== null) {
      const t = replay.t + (now - replay.last) * Number($("speed").value);
      replaySeek(t);
      if (replay.t >= replay.data.length_ms) replayPlay(false);
    }
    replay.last = now;
  }
  replayAsk();
}
function replayLane(lane, length) {
  const svg = $("lane"), W = 1000;
  svg.setAttribute("viewBox", `0 0 ${W} 10`);
  lane.forEach((span, i) => {
    const to = i + 1 < lane.length ? lane[i + 1].from : length;
    const x = length > 0 ? span.from / length * W : 0, w = length > 0 ? Math.max(0.5, (to - span.from) / length * W) : W;
    const r = el("rect", {x: x, y: 0, width: w, height: 10, fill: span.colour, "data-state": span.name}, svg);
    el("title", {}, r).textContent = `${span.name}: ${(span.from / 1000).toFixed(2)} to ${(to / 1000).toFixed(2)} s`;
  });
}
function startReplay(data) {
  replay.data = data;
  document.body.classList.add("replay");
  if (data.figures) fig = data.figures;
  if (data.course_map) courseMap = data.course_map;
  text("link", "replay of " + data.session);
  text("rnote", data.note);
  $("slider").max = data.length_ms;
  replayLane(data.lane, data.length_ms);
  $("play").onclick = () => replayPlay(!replay.playing);
  $("slider").oninput = () => { replay.last = null; replaySeek(Number($("slider").value)); };
  replaySeek(0);
  requestAnimationFrame(replayFrame);
}
// ---- end of the replay ----

fetch("/replay").then(r => r.ok ? r.json() : null).then(d => d && d.replay ? startReplay(d) : live())
  .catch(() => live());
requestAnimationFrame(draw);
</script>
</body></html>
)page";

}  // namespace

std::string_view trainer_page() { return kPage; }

}  // namespace andros::trainer
