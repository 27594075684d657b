/*
 * compare.html: the entries named in the address (?entries=ID,ID,...) side by side, a row
 * per metric (in the boards' order, the headline first), a column per entry. The numbers
 * come from window.SYMBENCH_ENTRIES (data/entries.js, written when the site was built),
 * loaded with <script src> because a browser blocks fetch() of a file:// URL.
 */
(function () {
  "use strict";

  var data = window.SYMBENCH_ENTRIES || {};
  var raw = new URLSearchParams(window.location.search).get("entries") || "";
  var ids = raw.split(",").filter(function (id) {
    return Object.prototype.hasOwnProperty.call(data, id);
  });
  var place = document.getElementById("compare");
  if (place === null || ids.length === 0) {
    return;
  }

  function element(tag, text) {
    var made = document.createElement(tag);
    if (text !== undefined) {
      made.textContent = text;
    }
    return made;
  }

  var entries = ids.map(function (id) {
    return data[id];
  });
  var order = [];
  var better = {};
  entries.forEach(function (entry) {
    entry.metrics.forEach(function (metric) {
      if (!(metric[0] in better)) {
        order.push(metric[0]);
        better[metric[0]] = metric[2];
      }
    });
  });

  var table = element("table");
  table.className = "compare";
  table.appendChild(element("caption", entries.length + " entries side by side: mean [95 % bootstrap interval] over seeds"));
  var head = table.createTHead().insertRow();
  head.appendChild(element("th", "metric")).setAttribute("scope", "col");
  entries.forEach(function (entry) {
    var cell = element("th");
    cell.setAttribute("scope", "col");
    cell.setAttribute("data-entry", ids[entries.indexOf(entry)]);
    var title = element("a", entry.title);
    title.href = entry.entry;
    cell.appendChild(title);
    cell.appendChild(element("span", entry.robot + ", " + entry.dataset + ", " + entry.protocol + " protocol, split " + entry.split)).className = "where";
    head.appendChild(cell);
  });
  var body = table.createTBody();
  order.forEach(function (name) {
    var row = body.insertRow();
    row.setAttribute("data-metric", name);
    var arrow = better[name] === "lower" ? " ↓" : better[name] === "higher" ? " ↑" : "";
    var label = element("th", name + arrow);
    label.setAttribute("scope", "row");
    row.appendChild(label);
    entries.forEach(function (entry) {
      var found = entry.metrics.filter(function (metric) {
        return metric[0] === name;
      });
      row.appendChild(element("td", found.length ? found[0][1] : "-"));
    });
  });
  place.replaceChildren(table);
})();
