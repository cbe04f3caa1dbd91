#include "report/html_report_assets.hpp"

namespace argus::report {

const std::string_view report_style = R"css(
body { font-family: sans-serif; margin: 1.5em auto; max-width: 1260px; color: #222; }
h1 { font-size: 1.5em; } h2 { font-size: 1.2em; margin-top: 1.6em; border-bottom: 1px solid #ccc; }
figure { margin: 1em 0; } figure img { max-width: 100%; border: 1px solid #ddd; }
figcaption { font-size: 0.9em; color: #555; }
table { border-collapse: collapse; font-size: 0.85em; }
th, td { border: 1px solid #ddd; padding: 2px 6px; text-align: left; vertical-align: top; }
th { background: #f3f3f3; } td.number { text-align: right; font-variant-numeric: tabular-nums; }
.scroll { overflow-x: auto; }
#log-controls { margin: 0.5em 0; } #log-controls input { width: 24em; }
#log { font-family: monospace; font-size: 0.8em; }
#status { font-size: 0.8em; color: #777; }
)css";

const std::string_view report_error_catcher = R"js(
window.reportErrors = [];
window.addEventListener('error', function (e) { window.reportErrors.push(String(e.message)); });
)js";

const std::string_view report_script = R"js(
(function () {
  'use strict';
  var data = document.getElementById('events-data');
  var events = data ? JSON.parse(data.textContent) : [];
  var kindSelect = document.getElementById('log-kind');
  var textInput = document.getElementById('log-text');
  var body = document.getElementById('log-body');
  var count = document.getElementById('log-count');
  var shownAtMost = 2000;
  var lines = events.map(function (e) { return JSON.stringify(e).toLowerCase(); });

  function details(e) {
    var parts = [];
    Object.keys(e).forEach(function (key) {
      if (key === 't' || key === 'tick' || key === 'source' || key === 'kind') return;
      parts.push(key + '=' + (typeof e[key] === 'object' ? JSON.stringify(e[key]) : e[key]));
    });
    return parts.join(' ');
  }

  function cell(row, text) {
    var td = document.createElement('td');
    td.textContent = text;
    row.appendChild(td);
  }

  function render() {
    if (!body) return;
    var kind = kindSelect ? kindSelect.value : '';
    var words = textInput ? textInput.value.toLowerCase().split(/\s+/).filter(Boolean) : [];
    var matches = 0;
    var fragment = document.createDocumentFragment();
    for (var i = 0; i < events.length; ++i) {
      var e = events[i];
      if (kind && e.kind !== kind) continue;
      var line = lines[i];
      if (!words.every(function (w) { return line.indexOf(w) >= 0; })) continue;
      ++matches;
      if (matches > shownAtMost) continue;
      var row = document.createElement('tr');
      cell(row, typeof e.t === 'number' ? e.t.toFixed(3) : '');
      cell(row, e.tick === undefined ? '' : String(e.tick));
      cell(row, e.source || '');
      cell(row, e.kind || '');
      cell(row, details(e));
      fragment.appendChild(row);
    }
    body.textContent = '';
    body.appendChild(fragment);
    if (count)
      count.textContent = matches + ' of ' + events.length + ' events' +
          (matches > shownAtMost ? ' (first ' + shownAtMost + ' shown)' : '');
  }

  if (kindSelect) {
    var kinds = {};
    events.forEach(function (e) { kinds[e.kind] = (kinds[e.kind] || 0) + 1; });
    Object.keys(kinds).sort().forEach(function (k) {
      var option = document.createElement('option');
      option.value = k;
      option.textContent = k + ' (' + kinds[k] + ')';
      kindSelect.appendChild(option);
    });
    kindSelect.addEventListener('change', render);
  }
  if (textInput) textInput.addEventListener('input', render);
  render();

  window.addEventListener('load', function () {
    var images = Array.prototype.slice.call(document.images);
    var broken = images.filter(function (img) { return !(img.complete && img.naturalWidth > 0); });
    var status = document.getElementById('status');
    status.dataset.images = String(images.length);
    status.dataset.broken = String(broken.length);
    status.dataset.errors = String(window.reportErrors.length);
    status.dataset.events = String(events.length);
    status.dataset.ready = 'yes';
    status.textContent = images.length + ' images (' + broken.length + ' broken), ' +
        events.length + ' events, ' + window.reportErrors.length + ' script errors';
  });
})();
)js";

}  // namespace argus::report
