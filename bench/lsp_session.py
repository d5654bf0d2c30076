#!/usr/bin/env python3
"""Latency benchmark of `kerf lsp` (issue 14 "What must be shown" 4): plays a scripted editing
session against the server over its stdin/stdout, as an editor does, and prints the figures for
bench/RESULTS.md.

    lsp_session.py KERF PROGRAM [--edits N] [--requests N] [--seed S] [--dialect D]

The session:
  1. initialize; didOpen PROGRAM; the time until the first publishDiagnostics of version 1 (the
     static findings) and until the complete one (after the dry run);
  2. N one-character edits (typing a digit into a number, or deleting one, at random lines), each
     waited for: the time from sending didChange to the static and to the complete diagnostics of
     that version;
  3. N hovers and N completions at random positions (a random line, a random column within it),
     first while nothing runs, then N hovers again right after an edit while the new version's
     analysis runs;
  4. the server's peak and current resident memory (/proc/PID/status VmHWM, VmRSS) against the
     document's size.
Times are wall-clock on the client side, including the pipe and JSON of both sides. Beside them, the
CPU time the server's threads used in the same span (/proc/PID/task/*/schedstat, nanoseconds): on a
shared machine the wall time grows with the load, the CPU time much less.
"""
import argparse
import json
import os
import queue
import random
import statistics
import subprocess
import sys
import threading
import time


class Client:
    def __init__(self, cmd):
        self.proc = subprocess.Popen(cmd, stdin=subprocess.PIPE, stdout=subprocess.PIPE, bufsize=0)
        self.messages = queue.Queue()
        self.next_id = 0
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        f = self.proc.stdout
        while True:
            line = f.readline()
            if not line:
                self.messages.put(None)
                return
            if line.lower().startswith(b'content-length:'):
                n = int(line.split(b':')[1])
                while f.readline() not in (b'\r\n', b'\n', b''):
                    pass
                body = b''
                while len(body) < n:
                    body += f.read(n - len(body))
                self.messages.put((time.perf_counter(), json.loads(body)))

    def send(self, msg):
        body = json.dumps(msg).encode()
        self.proc.stdin.write(b'Content-Length: %d\r\n\r\n' % len(body) + body)
        self.proc.stdin.flush()

    def notify(self, method, params):
        self.send({'jsonrpc': '2.0', 'method': method, 'params': params})

    def request(self, method, params):
        self.next_id += 1
        self.send({'jsonrpc': '2.0', 'id': self.next_id, 'method': method, 'params': params})
        return self.next_id

    def wait(self, match, timeout=600):
        end = time.perf_counter() + timeout
        while True:
            item = self.messages.get(timeout=max(0.001, end - time.perf_counter()))
            if item is None:
                raise EOFError('the server exited')
            when, msg = item
            if match(msg):
                return when, msg

    def call(self, method, params):
        start = time.perf_counter()
        i = self.request(method, params)
        when, msg = self.wait(lambda m: m.get('id') == i and 'method' not in m)
        return when - start, msg


def diagnostics_of(uri, version, phase):
    def match(m):
        if m.get('method') != 'textDocument/publishDiagnostics':
            return False
        p = m['params']
        return p['uri'] == uri and p.get('version') == version and p.get('kerf', {}).get('phase') == phase
    return match


def cpu_seconds(pid):
    total = 0
    for task in os.listdir(f'/proc/{pid}/task'):
        try:
            with open(f'/proc/{pid}/task/{task}/schedstat') as f:
                total += int(f.read().split()[0])
        except (FileNotFoundError, ProcessLookupError):
            pass   # a thread that ended: its time is in the process's, not read here
    return total / 1e9


def memory(pid):
    out = {}
    with open(f'/proc/{pid}/status') as f:
        for line in f:
            if line.startswith(('VmHWM', 'VmRSS')):
                key, value = line.split(':')
                out[key] = int(value.split()[0]) * 1024
    return out


def percentiles(values):
    v = sorted(values)
    pick = lambda q: v[min(len(v) - 1, int(round(q * (len(v) - 1))))]
    return {'n': len(v), 'p50_ms': pick(0.5) * 1e3, 'p99_ms': pick(0.99) * 1e3, 'max_ms': v[-1] * 1e3, 'mean_ms': statistics.mean(v) * 1e3}


def fmt(p):
    answered = f", {p['answered']} with a result" if 'answered' in p else ''
    return f"p50 {p['p50_ms']:.2f} ms, p99 {p['p99_ms']:.2f} ms, max {p['max_ms']:.2f} ms (n={p['n']}{answered})"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('kerf')
    ap.add_argument('program')
    ap.add_argument('--edits', type=int, default=20)
    ap.add_argument('--requests', type=int, default=1000)
    ap.add_argument('--seed', type=int, default=1)
    ap.add_argument('--dialect', default='fanuc-mill')
    a = ap.parse_args()
    rng = random.Random(a.seed)
    text = open(a.program, encoding='utf-8', errors='surrogateescape').read()
    lines = text.split('\n')
    uri = 'file://' + os.path.abspath(a.program)
    c = Client([a.kerf, 'lsp'])
    c.call('initialize', {'processId': os.getpid(), 'rootUri': None, 'capabilities': {},
                          'initializationOptions': {'dialect': a.dialect}})
    c.notify('initialized', {})
    result = {'program': a.program, 'bytes': len(text.encode()), 'lines': len(lines) - (1 if lines[-1] == '' else 0)}

    # 1. didOpen
    body = json.dumps({'jsonrpc': '2.0', 'method': 'textDocument/didOpen',
                       'params': {'textDocument': {'uri': uri, 'languageId': 'gcode', 'version': 1, 'text': text}}}).encode()
    cpu0 = cpu_seconds(c.proc.pid)
    start = time.perf_counter()
    c.proc.stdin.write(b'Content-Length: %d\r\n\r\n' % len(body) + body)
    c.proc.stdin.flush()
    t_static, m = c.wait(diagnostics_of(uri, 1, 'static'))
    result['open_static_cpu_s'] = cpu_seconds(c.proc.pid) - cpu0
    result['open_static_s'] = t_static - start
    result['open_static_count'] = len(m['params']['diagnostics'])
    t_complete, m = c.wait(diagnostics_of(uri, 1, 'complete'))
    result['open_complete_s'] = t_complete - start
    result['open_complete_count'] = len(m['params']['diagnostics'])
    result['memory_after_open'] = memory(c.proc.pid)

    # 2. one-character edits
    version = 1
    statics, completes, static_cpu = [], [], []
    for i in range(a.edits):
        version += 1
        line = rng.randrange(len(lines))
        s = lines[line]
        digits = [k for k, ch in enumerate(s) if ch.isdigit()]
        if digits and i % 2:
            col = rng.choice(digits)   # delete a digit
            change = {'range': {'start': {'line': line, 'character': col}, 'end': {'line': line, 'character': col + 1}}, 'text': ''}
            lines[line] = s[:col] + s[col + 1:]
        else:
            col = rng.choice(digits) if digits else len(s)   # type a digit into a number
            change = {'range': {'start': {'line': line, 'character': col}, 'end': {'line': line, 'character': col}}, 'text': '7'}
            lines[line] = s[:col] + '7' + s[col:]
        cpu0 = cpu_seconds(c.proc.pid)
        start = time.perf_counter()
        c.notify('textDocument/didChange', {'textDocument': {'uri': uri, 'version': version}, 'contentChanges': [change]})
        t1, _ = c.wait(diagnostics_of(uri, version, 'static'))
        static_cpu.append(cpu_seconds(c.proc.pid) - cpu0)
        t2, _ = c.wait(diagnostics_of(uri, version, 'complete'))
        statics.append(t1 - start)
        completes.append(t2 - start)
    result['edit_static'] = percentiles(statics)
    result['edit_static_cpu'] = percentiles(static_cpu)
    result['edit_complete'] = percentiles(completes)

    # 3. hovers and completions at random positions, the server idle
    def random_position():
        line = rng.randrange(len(lines))
        return {'line': line, 'character': rng.randrange(len(lines[line]) + 1)}
    for method, key in (('textDocument/hover', 'hover_idle'), ('textDocument/completion', 'completion_idle')):
        times, answered = [], 0
        for _ in range(a.requests):
            dt, msg = c.call(method, {'textDocument': {'uri': uri}, 'position': random_position()})
            assert 'result' in msg, msg
            answered += msg['result'] not in (None, [], {})
            times.append(dt)
        result[key] = percentiles(times)
        result[key]['answered'] = answered   # requests with a non-empty result (a hover on a blank has none)
    # ...and right after an edit, while the new version's analysis (static rules, dry run) runs.
    version += 1
    c.notify('textDocument/didChange', {'textDocument': {'uri': uri, 'version': version},
                                        'contentChanges': [{'range': {'start': {'line': 0, 'character': 0}, 'end': {'line': 0, 'character': 0}}, 'text': ''}]})
    times = []
    for _ in range(a.requests):
        dt, msg = c.call('textDocument/hover', {'textDocument': {'uri': uri}, 'position': random_position()})
        times.append(dt)
    result['hover_during_analysis'] = percentiles(times)
    c.call('kerf/waitForAnalysis', None)
    result['memory_end'] = memory(c.proc.pid)
    c.call('shutdown', None)
    c.notify('exit', None)
    result['exit_code'] = c.proc.wait(timeout=60)

    mb = result['bytes'] / 1e6
    print(json.dumps(result, indent=1))
    print(f"\n{result['program']}: {result['lines']} lines, {mb:.1f} MB")
    print(f"  didOpen -> static diagnostics {result['open_static_s']*1e3:.0f} ms (server CPU {result['open_static_cpu_s']*1e3:.0f} ms), "
          f"complete (dry run) {result['open_complete_s']*1e3:.0f} ms")
    print(f"  one-character edit -> static: {fmt(result['edit_static'])}")
    print(f"    server CPU in that span: {fmt(result['edit_static_cpu'])}")
    print(f"  one-character edit -> complete: {fmt(result['edit_complete'])}")
    print(f"  hover (idle): {fmt(result['hover_idle'])}")
    print(f"  completion (idle): {fmt(result['completion_idle'])}")
    print(f"  hover (during analysis): {fmt(result['hover_during_analysis'])}")
    peak = max(result['memory_after_open']['VmHWM'], result['memory_end']['VmHWM'])
    print(f"  memory: peak {peak/1e6:.0f} MB = {peak/result['bytes']:.1f}x the document; "
          f"resident at the end {result['memory_end']['VmRSS']/1e6:.0f} MB = {result['memory_end']['VmRSS']/result['bytes']:.1f}x")


if __name__ == '__main__':
    main()
