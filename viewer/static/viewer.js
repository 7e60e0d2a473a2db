// The viewer page: one WebSocket to the server (hello, then frames), the HUD, the beliefs
// toggle, the replay controls and timeline, and window.viewer, the API that tests and the
// exporter drive.
import { drawField, drawTruth, makeView } from "./draw.js";
import { drawTimeline, markerAt, xToTime } from "./timeline.js";

const $ = (id) => document.getElementById(id);
const GAME_STATES = ["INITIAL", "READY", "SET", "PLAYING", "FINISHED", "STANDBY"];
const canvas = $("field");
const ctx = canvas.getContext("2d");
const params = new URLSearchParams(location.search);
if (params.has("export")) document.body.classList.add("export");
let showBeliefs = params.get("beliefs") !== "0"; // ?beliefs=0 starts with them hidden
$("beliefs").checked = showBeliefs;
const strip = $("timeline");
const stripCtx = strip.getContext("2d");
let strips = null; // what the timeline drew last: markers with their x, the playhead

let hello = null;   // {mode, source, match (TL_MATCH: null live until it comes), replay?}
let frame = null;   // the last frame received: {truth, sense, game, status, events, replay?, ack}
let socket = null;
let nextSeq = 1;
let scrubbing = false;
const pending = [];  // [seq, resolve] of commands not yet answered by a drawn frame
let markReady;
const ready = new Promise((resolve) => { markReady = resolve; });

function connect() {
  socket = new WebSocket(`ws://${location.host}/ws`);
  socket.onmessage = (event) => {
    const message = JSON.parse(event.data);
    if (message.type === "hello") onHello(message);
    else if (message.type === "frame") onFrame(message);
  };
  socket.onclose = () => {
    $("source").textContent = "disconnected, retrying…";
    setTimeout(connect, 1000);
  };
}

function onHello(message) {
  hello = message;
  const replay = message.mode === "replay";
  $("controls").hidden = !replay;
  strip.hidden = !replay;
  $("source").textContent = replay ? `replay: ${message.source}` : `live: ${message.source}`;
  if (replay) {
    const scrub = $("scrub");
    scrub.min = message.replay.t0;
    scrub.max = message.replay.t1;
    $("speed").replaceChildren(...message.speeds.map((x) => new Option(`${x}x`, x, x === 1, x === 1)));
  }
  draw();
}

function onFrame(message) {
  frame = message;
  showHud(); // first: the HUD's layout decides the canvas size
  draw();
  while (pending.length && message.ack !== null && pending[0][0] <= message.ack) pending.shift()[1](state());
  if (message.truth) markReady(state());
}

let drawn = null;
let lastView = null;
function draw() {
  if (!hello) return;
  const box = canvas.getBoundingClientRect(), dpr = window.devicePixelRatio || 1;
  canvas.width = Math.round(box.width * dpr);
  canvas.height = Math.round(box.height * dpr);
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  const match = hello.match;
  drawn = null;
  if (match) {
    const view = makeView(match.field, box.width, box.height);
    lastView = view;
    drawField(ctx, view, match.field);
    drawn = frame && frame.truth
      ? drawTruth(ctx, view, match, frame.truth, frame.sense, frame.beliefs, showBeliefs) : null;
  } else {
    ctx.fillStyle = "#1b1f24";
    ctx.fillRect(0, 0, box.width, box.height);
  }
  if (!drawn) {
    ctx.fillStyle = "#fff";
    ctx.font = "16px 'DejaVu Sans', sans-serif";
    ctx.textAlign = "center";
    ctx.fillText(match ? "waiting for TL_TRUTH…" : "waiting for the match's TL_MATCH…", box.width / 2, box.height / 2);
  }
  drawStrip();
  const out = $("state");
  out.textContent = JSON.stringify(state());
  out.dataset.frame = frame && frame.truth ? frame.truth.frame : "";
}

function drawStrip() {
  strips = null;
  if (!hello || !hello.replay || strip.hidden) return;
  const box = strip.getBoundingClientRect(), dpr = window.devicePixelRatio || 1;
  strip.width = Math.round(box.width * dpr);
  strip.height = Math.round(box.height * dpr);
  stripCtx.setTransform(dpr, 0, 0, dpr, 0, 0);
  const now = frame && frame.replay ? frame.replay.t : null;
  strips = { width: box.width, height: box.height,
    ...drawTimeline(stripCtx, box.width, box.height, [hello.replay.t0, hello.replay.t1], hello.timeline || [], now) };
}

function stripX(event) {
  return event.clientX - strip.getBoundingClientRect().left;
}

strip.addEventListener("click", (event) => {
  if (!strips) return;
  const x = stripX(event), marker = markerAt(strips.markers, x);
  // A marker shows its effect: the first frame at or after it (the goal scored, the robot down).
  command(marker ? { cmd: "seek", t: marker.t, after: true }
    : { cmd: "seek", t: xToTime(x, [hello.replay.t0, hello.replay.t1], strips.width) });
});
strip.addEventListener("mousemove", (event) => {
  const marker = strips && markerAt(strips.markers, stripX(event));
  strip.title = marker ? `${marker.t.toFixed(1)} s ${marker.kind}: ${marker.text}` : "click to jump there";
});

function setBeliefs(on) {
  showBeliefs = Boolean(on);
  $("beliefs").checked = showBeliefs;
  draw();
  return state();
}

function state() {
  const truth = frame && frame.truth;
  return {
    mode: hello && hello.mode,
    canvas: { width: canvas.clientWidth, height: canvas.clientHeight },
    scale_px_per_mm: lastView ? lastView.s : null,
    field: hello && hello.match ? hello.match.field : null,
    utime: truth ? truth.utime : null,
    frame: truth ? truth.frame : null,
    game: frame ? frame.game : null,
    replay: frame ? frame.replay || null : null,
    ack: frame ? frame.ack : null,
    ball: drawn ? drawn.ball : null,
    robots: drawn ? drawn.robots : [],
    show_beliefs: showBeliefs,
    beliefs: drawn ? drawn.beliefs : [],
    timeline: strips,
    events: frame ? frame.events || [] : [],
  };
}

function clock(secs) {
  const s = Math.max(0, secs | 0);
  return `${String(Math.floor(s / 60)).padStart(2, "0")}:${String(s % 60).padStart(2, "0")}`;
}

const TEAM_NAMES = ["Blue", "Red"];

function showHud() {
  const { game, truth, replay, status, events } = frame;
  if (game) {
    $("score0").textContent = game.score[0];
    $("score1").textContent = game.score[1];
    $("clock").textContent = clock(game.secs_remaining);
    $("game-state").textContent = `${GAME_STATES[game.state] || game.state} · ${game.first_half ? "1st" : "2nd"} half`;
  }
  if (truth) $("simtime").textContent = `sim ${(truth.utime / 1e6).toFixed(2)} s · frame ${truth.frame}`;
  if (replay) {
    $("play").textContent = replay.playing ? "Pause" : "Play";
    $("scrub-time").textContent = `${replay.t.toFixed(2)} s`;
    if (!scrubbing) $("scrub").value = replay.t;
    $("speed").value = replay.speed;
  }
  $("robots").replaceChildren(...(status || []).map((s) => {
    const li = document.createElement("li");
    li.className = `team${s.team}`;
    li.textContent = `${TEAM_NAMES[s.team]} ${s.player}: ${s.state}, ${s.frames_missed} missed, ` +
      `behaviour ${s.cpu_mean_us} µs mean`;
    li.title = s.detail;
    return li;
  }));
  $("events").replaceChildren(...(events || []).map((e) => {
    const li = document.createElement("li");
    const team = TEAM_NAMES[e.team], who = team ? ` ${team}${e.player ? ` ${e.player}` : ""}` : "";
    li.className = `team${e.team}`;
    li.textContent = `${(e.utime / 1e6).toFixed(1)} s ${e.kind}${who}: ${e.text}`;
    return li;
  }));
}

// Sends a replay command; resolves with the page state once the answering frame is drawn.
async function command(cmd) {
  await ready;
  const seq = nextSeq++;
  return new Promise((resolve) => {
    pending.push([seq, resolve]);
    socket.send(JSON.stringify({ ...cmd, seq }));
  });
}

$("play").onclick = () => command({ cmd: "toggle" });
$("step-back").onclick = () => command({ cmd: "step", n: -1 });
$("step-fwd").onclick = () => command({ cmd: "step", n: 1 });
$("speed").onchange = (e) => command({ cmd: "speed", x: Number(e.target.value) });
$("scrub").addEventListener("pointerdown", () => { scrubbing = true; });
$("scrub").addEventListener("pointerup", () => { scrubbing = false; });
$("scrub").addEventListener("change", () => { scrubbing = false; });
$("scrub").addEventListener("input", (e) => command({ cmd: "seek", t: Number(e.target.value) }));
$("beliefs").addEventListener("change", (e) => setBeliefs(e.target.checked));
window.addEventListener("keydown", (e) => {
  const typing = e.target.tagName === "SELECT" || (e.target.tagName === "INPUT" && e.target.type !== "checkbox");
  if (!hello || typing) return;
  if (e.key === "b") setBeliefs(!showBeliefs);
  else if (hello.mode !== "replay") return;
  else if (e.key === " ") command({ cmd: "toggle" });
  else if (e.key === "ArrowLeft") command({ cmd: "step", n: -1 });
  else if (e.key === "ArrowRight") command({ cmd: "step", n: 1 });
  else return;
  e.preventDefault();
});
new ResizeObserver(() => draw()).observe($("stage"));
new ResizeObserver(() => draw()).observe(strip);

window.viewer = {
  ready,
  state: () => state(),
  command,
  play: () => command({ cmd: "play" }),
  pause: () => command({ cmd: "pause" }),
  step: (n = 1) => command({ cmd: "step", n }),
  seek: (t) => command({ cmd: "seek", t }),
  setSpeed: (x) => command({ cmd: "speed", x }),
  setBeliefs: async (on) => setBeliefs(on),
};
connect();
