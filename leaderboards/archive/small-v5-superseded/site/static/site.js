/*
 * Sorting and filtering of the leaderboard tables: plain JavaScript, no framework, nothing
 * fetched, so the pages work opened from disk (file://) as well as from any static host.
 *
 * Sorting: a click on a header of a table.board sorts that table's rows by the column; a
 * second click on the same header reverses the order. Each cell's data-value is what is
 * compared: numbers (th[data-type="number"]) as numbers (the mean over seeds at full
 * precision, not the rounded text shown), text as text. Cells without a value (a metric
 * that a model has no record of) go last in either direction. Equal values keep their
 * previous order. The header's aria-sort says which column orders the table, and how.
 *
 * Filtering: the select#model-filter shows only the rows (tr[data-model]) of the chosen
 * model, in every table of the page; its empty choice shows every row.
 */
(function () {
  "use strict";

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

  function sortTable(table, header) {
    var index = header.cellIndex;
    var numeric = header.getAttribute("data-type") === "number";
    var descending = header.getAttribute("aria-sort") === "ascending";
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
    header.setAttribute("aria-sort", descending ? "descending" : "ascending");
  }

  function filterRows(model) {
    document.querySelectorAll("tr[data-model]").forEach(function (row) {
      row.hidden = model !== "" && row.getAttribute("data-model") !== model;
    });
  }

  document.querySelectorAll("table.board").forEach(function (table) {
    Array.prototype.forEach.call(table.tHead.rows[0].cells, function (header) {
      header.addEventListener("click", function () {
        sortTable(table, header);
      });
    });
  });

  var filter = document.getElementById("model-filter");
  if (filter !== null) {
    filter.addEventListener("change", function () {
      filterRows(filter.value);
    });
    filterRows(filter.value);  // a value the browser kept from before a reload
  }
})();
