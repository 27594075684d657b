/*
 * The leaderboard tables' sorting, model filter and compare boxes, with the view kept in
 * the page's address: plain JavaScript, no framework, nothing fetched, so the pages work
 * opened from disk (file://) as well as from any static host.
 *
 * Sorting: a click on a header of a table.board sorts that table's rows by the column. The
 * first click sorts the best first (th[data-better] says whether lower or higher is
 * better; a column without a better direction sorts ascending), a second click on the same
 * header reverses. Each cell's data-value is what is compared: numbers
 * (th[data-type="number"]) as numbers (the mean over seeds at full precision, not the
 * rounded text shown), text as text. Cells without a value go last in either direction;
 * equal values keep their previous order. The header's aria-sort says which column orders
 * the table, and how.
 *
 * Filtering: the boxes of #model-filter choose the models whose rows (tr[data-model]) show,
 * in every table of the page.
 *
 * Compare: the boxes of the rows (input.compare) choose entries; #compare-link leads to
 * compare.html with their ids.
 *
 * The address: ?models=a,b (absent: every model), &sort=TABLE:COLUMN:ascending|descending,...
 * (TABLE the id of the table's section) and &compare=ID,... are written as the view changes
 * (history.replaceState) and read when the page loads, so a link reproduces the view.
 */
(function () {
  "use strict";

  var params = new URLSearchParams(window.location.search);

  function list(name) {
    var raw = params.get(name);
    return raw === null || raw === "" ? [] : raw.split(",");
  }

  function keep(name, values) {
    if (values.length === 0) {
      params.delete(name);
    } else {
      params.set(name, values.join(","));
    }
    var query = params.toString();
    var url = window.location.pathname + (query ? "?" + query : "") + window.location.hash;
    window.history.replaceState(null, "", url);
  }

  function each(selector, action) {
    Array.prototype.forEach.call(document.querySelectorAll(selector), action);
  }

  // sorting

  function sortValue(row, index, numeric) {
    var raw = row.cells[index].getAttribute("data-value");
    if (raw === null || raw === "") {
      return null;
    }
    return numeric ? parseFloat(raw) : raw;
  }

  function compare(a, b, numeric) {
    if (numeric) {
      return a - b;
    }
    return a < b ? -1 : a > b ? 1 : 0;
  }

  function tableId(table) {
    var section = table.closest("section[id]");
    return section === null ? "" : section.id;
  }

  function sortTable(table, header, direction) {
    var index = header.cellIndex;
    var numeric = header.getAttribute("data-type") === "number";
    var descending = direction === "descending";
    var body = table.tBodies[0];
    var rows = Array.prototype.slice.call(body.rows);
    rows.sort(function (x, y) {
      var a = sortValue(x, index, numeric);
      var b = sortValue(y, index, numeric);
      if (a === null || b === null) {
        return (a === null) - (b === null);
      }
      var order = compare(a, b, numeric);
      return descending ? -order : order;
    });
    rows.forEach(function (row) {
      body.appendChild(row);
    });
    Array.prototype.forEach.call(table.tHead.rows[0].cells, function (cell) {
      cell.removeAttribute("aria-sort");
    });
    header.setAttribute("aria-sort", direction);
  }

  function nextDirection(header) {
    var now = header.getAttribute("aria-sort");
    if (now !== null) {
      return now === "ascending" ? "descending" : "ascending";
    }
    return header.getAttribute("data-better") === "higher" ? "descending" : "ascending";
  }

  var sorts = {};  // table id -> "column:direction", as the address keeps them

  function keepSorts() {
    keep("sort", Object.keys(sorts).sort().map(function (id) {
      return id + ":" + sorts[id];
    }));
  }

  each("table.board", function (table) {
    Array.prototype.forEach.call(table.tHead.rows[0].cells, function (header) {
      header.addEventListener("click", function () {
        var direction = nextDirection(header);
        sortTable(table, header, direction);
        sorts[tableId(table)] = header.getAttribute("data-column") + ":" + direction;
        keepSorts();
      });
    });
  });

  list("sort").forEach(function (kept) {
    var parts = kept.split(":");
    var section = document.getElementById(parts[0]);
    var table = section === null ? null : section.querySelector("table.board");
    if (table === null || parts.length !== 3) {
      return;
    }
    Array.prototype.forEach.call(table.tHead.rows[0].cells, function (header) {
      if (header.getAttribute("data-column") === parts[1]) {
        sortTable(table, header, parts[2] === "descending" ? "descending" : "ascending");
        sorts[parts[0]] = parts[1] + ":" + header.getAttribute("aria-sort");
      }
    });
  });

  // the model filter

  var boxes = document.querySelectorAll("#model-filter input[name=model]");

  function filterRows() {
    var shown = {};
    var all = true;
    Array.prototype.forEach.call(boxes, function (box) {
      shown[box.value] = box.checked;
      all = all && box.checked;
    });
    each("tr[data-model]", function (row) {
      row.hidden = !shown[row.getAttribute("data-model")];
    });
    return all;
  }

  if (boxes.length > 0) {
    var chosen = list("models");
    Array.prototype.forEach.call(boxes, function (box) {
      box.checked = chosen.length === 0 || chosen.indexOf(box.value) >= 0;
      box.addEventListener("change", function () {
        var all = filterRows();
        keep("models", all ? [] : Array.prototype.filter.call(boxes, function (b) {
          return b.checked;
        }).map(function (b) {
          return b.value;
        }));
      });
    });
    filterRows();
  }

  // compare boxes

  var link = document.getElementById("compare-link");
  var counted = document.getElementById("compare-count");

  function chosenEntries() {
    return Array.prototype.filter.call(document.querySelectorAll("input.compare"), function (box) {
      return box.checked;
    }).map(function (box) {
      return box.value;
    });
  }

  function showChoice() {
    var ids = chosenEntries();
    if (link !== null) {
      var target = link.getAttribute("href").split("?")[0];
      link.setAttribute("href", ids.length ? target + "?entries=" + ids.join(",") : target);
    }
    if (counted !== null) {
      counted.textContent = ids.length === 0 ? "none chosen" : ids.length + " chosen";
    }
    return ids;
  }

  var kept = list("compare");
  each("input.compare", function (box) {
    box.checked = kept.indexOf(box.value) >= 0;
    box.addEventListener("change", function () {
      keep("compare", showChoice());
    });
  });
  showChoice();
})();
