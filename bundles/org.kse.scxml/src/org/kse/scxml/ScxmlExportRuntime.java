package org.kse.scxml;

/**
 * The data model's script: the blackboards, the hub, the running counters and the timers of
 * docs/semantics.md in ECMAScript (docs/adr/0038-scxml-mapping.md, "The host"). The host talks to
 * it through three data items: it appends commands to {@code kse_in} (a JSON array, each with a
 * rising {@code seq}), which the script applies in order the next time it runs, before anything
 * else; {@code kse_done} is the last seq applied; {@code kse.flush()} hands the host what it must
 * know (publishes for its own readers, wake-up times, activities started) through
 * {@code <log label="kse.out">}.
 */
final class ScxmlExportRuntime {

	private ScxmlExportRuntime() {
	}

	static final String SCRIPT = """
			var kse = {
			  now: 0, done: 0, boards: {}, retained: {}, running: {}, runs: [], types: {}, chosen: {}, outbox: [],
			  subscriptions: {}, timers: [],
			  sync: function () {
			    if (typeof kse_in !== 'string' || kse_in === '') return;
			    var commands = JSON.parse(kse_in);
			    for (var i = 0; i < commands.length; i++) {
			      var c = commands[i];
			      if (c.seq <= kse.done) continue;
			      kse.done = c.seq;
			      if (c.op === 'clock') kse.now = c.now;
			      else if (c.op === 'publish') kse.deliver(null, c.topic, c.kind, c.type, c.msg);
			      else if (c.op === 'begin') kse.process(c.region);
			      else if (c.op === 'types') kse.types = c.types;
			      else if (c.op === 'done') kse.ended(c.activity);
			    }
			    kse_done = kse.done;
			  },
			  board: function (label) {
			    var b = kse.boards[label];
			    if (!b) b = kse.boards[label] = { topics: {}, inbox: [], state: {}, signals: {}, data: {} };
			    return b;
			  },
			  subscribe: function (label, topic) {
			    var b = kse.board(label);
			    if (b.topics[topic]) return;
			    b.topics[topic] = true;
			    for (var key in kse.retained) {
			      if (key.indexOf(topic + '|') === 0) b.inbox.push({ key: key, kind: 'State', msg: kse.retained[key] });
			    }
			  },
			  start: function () {
			    kse.sync();
			    for (var label in kse.subscriptions) {
			      kse.board(label);
			      var topics = kse.subscriptions[label];
			      for (var i = 0; i < topics.length; i++) kse.subscribe(label, topics[i]);
			    }
			    for (var j = 0; j < kse.timers.length; j++) kse.deliver(kse.timers[j][0], kse.timers[j][1], 'State', 'TimeoutMsg', {});
			  },
			  deliver: function (from, topic, kind, type, msg) {
			    var key = topic + '|' + type;
			    if (kind === 'State') kse.retained[key] = msg;
			    for (var label in kse.boards) {
			      var b = kse.boards[label];
			      if (label === from) kse.keep(b, { key: key, kind: kind, msg: msg });
			      else if (b.topics[topic]) b.inbox.push({ key: key, kind: kind, msg: msg });
			    }
			    if (from !== null) kse.outbox.push({ publish: { topic: topic, kind: kind, type: type, msg: msg } });
			  },
			  keep: function (b, e) {
			    if (e.kind === 'State') b.state[e.key] = e.msg;
			    else if (e.kind === 'Signal') (b.signals[e.key] = b.signals[e.key] || []).push(e.msg);
			    else (b.data[e.key] = b.data[e.key] || []).push(e.msg);
			  },
			  process: function (label) {
			    var b = kse.board(label);
			    var inbox = b.inbox;
			    b.inbox = [];
			    for (var i = 0; i < inbox.length; i++) kse.keep(b, inbox[i]);
			  },
			  processMessages: function (label) { kse.sync(); kse.process(label); },
			  read: function (b, topic, kind, type) {
			    var key = topic + '|' + type;
			    if (kind === 'State') return b.state[key] === undefined ? null : b.state[key];
			    if (kind === 'Signal') { var q = b.signals[key]; return q && q.length ? q.shift() : null; }
			    var h = b.data[key];
			    return h && h.length ? h[h.length - 1] : null;
			  },
			  guard: function (label, reads, refreshes, decide) {
			    kse.sync();
			    var b = kse.board(label);
			    var m = [];
			    for (var i = 0; i < reads.length; i++) m.push(kse.read(b, reads[i][0], reads[i][1], reads[i][2]));
			    if (refreshes) kse.process(label);
			    return decide(m) ? true : false;
			  },
			  idle: function (regions) {
			    kse.sync();
			    for (var i = 0; i < regions.length; i++) if (kse.running[regions[i]]) return false;
			    return true;
			  },
			  choose: function (chain, decide) { kse.chosen[chain] = decide(); return kse.chosen[chain]; },
			  timeoutCheck: function (msg) {
			    if (msg === null || msg.wakeup === undefined || msg.wakeup === '') return false;
			    return kse.now >= Number(msg.wakeup);
			  },
			  setTimeout: function (label, topic, ms) {
			    kse.sync();
			    var at = kse.now + ms;
			    kse.deliver(label, topic, 'State', 'TimeoutMsg', { wakeup: String(at) });
			    kse.outbox.push({ wakeup: at });
			  },
			  publish: function (label, topic, kind, type, path, setter, value) {
			    kse.sync();
			    var msg = {}, at = msg, t = type;
			    for (var i = 0; i < path.length; i++) {
			      var f = kse.field(t, path[i]);
			      at = at[f.name] = {};
			      t = f.type;
			    }
			    at[kse.field(t, setter).name] = value;
			    kse.deliver(label, topic, kind, type, msg);
			  },
			  enterBasic: function (region, activity, state) {
			    kse.sync();
			    kse.running[region] = (kse.running[region] || 0) + 1;
			    kse.runs.push({ activity: activity, region: region });
			    kse.outbox.push({ start: activity, state: state, region: region });
			  },
			  activityDone: function (activity) { kse.sync(); kse.ended(activity); },
			  ended: function (activity) {
			    for (var i = 0; i < kse.runs.length; i++) {
			      if (kse.runs[i].activity === activity) {
			        kse.running[kse.runs[i].region]--;
			        kse.runs.splice(i, 1);
			        return;
			      }
			    }
			  },
			  flush: function () { var out = JSON.stringify(kse.outbox); kse.outbox = []; return out; },
			  field: function (type, name) {
			    var fields = kse.types[type], lower = name.toLowerCase();
			    if (fields && fields[lower]) return { name: fields[lower][0], def: fields[lower][1], type: fields[lower][2] };
			    return { name: lower, def: undefined, type: '' };
			  },
			  member: function (msg, type, path) {
			    var at = msg, t = type;
			    for (var i = 0; i < path.length; i++) {
			      var name = path[i][0];
			      if (/_size$/.test(name)) {
			        var list = at === null || at === undefined ? undefined : at[kse.field(t, name.slice(0, -5)).name];
			        return list ? list.length : 0;
			      }
			      var f = kse.field(t, name);
			      var v = at === null || at === undefined ? undefined : at[f.name];
			      if (path[i].length > 1) v = v === undefined ? undefined : v[path[i][1]];
			      if (v === undefined) v = f.type ? {} : f.def;
			      at = v;
			      t = f.type;
			    }
			    return at;
			  },
			  helpers: {
			    slack: 1e-6,
			    within: function (value, centre, tolerance) { return Math.abs(value - centre) <= tolerance + kse.helpers.slack; },
			    ball: function (w) { return kse.member(w, 'WorldInfo', [['balls_size']]) > 0; },
			    readyToKick: function (w) {
			      if (w === null || !kse.helpers.ball(w)) return false;
			      var x = Number(kse.member(w, 'WorldInfo', [['balls', 0], ['relativex']]));
			      var y = Number(kse.member(w, 'WorldInfo', [['balls', 0], ['relativey']]));
			      return kse.helpers.within(x, 0.122, 0.012) && kse.helpers.within(Math.abs(y), 0.03, 0.03);
			    },
			    ballAway: function (w) {
			      if (w === null || !kse.helpers.ball(w)) return false;
			      var x = Number(kse.member(w, 'WorldInfo', [['balls', 0], ['relativex']]));
			      var y = Number(kse.member(w, 'WorldInfo', [['balls', 0], ['relativey']]));
			      return Math.sqrt(x * x + y * y) > 0.8 + kse.helpers.slack;
			    },
			    robotInPosition: function (w, p) {
			      if (w === null || p === null) return false;
			      var pose = w[kse.field('WorldInfo', 'myposition').name];
			      if (pose === undefined) return false;
			      var h = kse.helpers, a = Number(kse.member(w, 'WorldInfo', [['myposition'], ['phi']])) - Number(kse.member(p, 'PositionMessage', [['theta']]));
			      a = ((a + Math.PI) % (2 * Math.PI) + 2 * Math.PI) % (2 * Math.PI) - Math.PI;
			      return h.within(Number(kse.member(w, 'WorldInfo', [['myposition'], ['x']])), Number(kse.member(p, 'PositionMessage', [['posx']])), 0.1) &&
			        h.within(Number(kse.member(w, 'WorldInfo', [['myposition'], ['y']])), Number(kse.member(p, 'PositionMessage', [['posy']])), 0.1) &&
			        h.within(a, 0, 0.39269908169872414);
			    }
			  }
			};
			""";
}
