// Pan and zoom on the SVG's viewBox, findings and elements that point at each other.
(function () {
  'use strict';
  var svg = document.querySelector('#diagram > svg');
  var data = JSON.parse(document.getElementById('rsaml-data').textContent);
  var box = svg.viewBox.baseVal;
  var full = { x: box.x, y: box.y, w: box.width, h: box.height };
  var view = { x: full.x, y: full.y, w: full.w, h: full.h };
  svg.removeAttribute('width');
  svg.removeAttribute('height');

  function apply() {
    svg.setAttribute('viewBox', view.x + ' ' + view.y + ' ' + view.w + ' ' + view.h);
  }
  function toDiagram(clientX, clientY) {
    var point = svg.createSVGPoint();
    point.x = clientX;
    point.y = clientY;
    return point.matrixTransform(svg.getScreenCTM().inverse());
  }
  function zoom(factor, centre) {
    view.x = centre.x - (centre.x - view.x) * factor;
    view.y = centre.y - (centre.y - view.y) * factor;
    view.w *= factor;
    view.h *= factor;
    apply();
  }
  function middle() {
    return { x: view.x + view.w / 2, y: view.y + view.h / 2 };
  }
  svg.addEventListener('wheel', function (e) {
    e.preventDefault();
    zoom(e.deltaY < 0 ? 0.8 : 1.25, toDiagram(e.clientX, e.clientY));
  }, { passive: false });
  document.getElementById('zoom-in').addEventListener('click', function () { zoom(0.8, middle()); });
  document.getElementById('zoom-out').addEventListener('click', function () { zoom(1.25, middle()); });
  document.getElementById('zoom-fit').addEventListener('click', function () {
    view = { x: full.x, y: full.y, w: full.w, h: full.h };
    apply();
  });

  var drag = null;
  var dragged = false;
  svg.addEventListener('mousedown', function (e) {
    drag = { x: e.clientX, y: e.clientY, vx: view.x, vy: view.y };
    dragged = false;
  });
  window.addEventListener('mousemove', function (e) {
    if (!drag) { return; }
    var dx = e.clientX - drag.x;
    var dy = e.clientY - drag.y;
    if (Math.abs(dx) + Math.abs(dy) > 3) { dragged = true; }
    var rect = svg.getBoundingClientRect();
    var scale = Math.max(view.w / rect.width, view.h / rect.height);
    view.x = drag.vx - dx * scale;
    view.y = drag.vy - dy * scale;
    apply();
  });
  window.addEventListener('mouseup', function () { drag = null; });

  function highlight(elements) {
    var previous = svg.querySelectorAll('.highlight');
    for (var i = 0; i < previous.length; i++) { previous[i].classList.remove('highlight'); }
    elements.forEach(function (e) { e.classList.add('highlight'); });
  }
  // Zooms so that the elements span about 40 % of the diagram's width or height (never more than two
  // screen pixels per unit, so a port is not blown up) and centres them.
  function focus(elements) {
    if (elements.length === 0) { return; }
    var x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    elements.forEach(function (e) {
      var b = e.getBBox();
      x0 = Math.min(x0, b.x); y0 = Math.min(y0, b.y);
      x1 = Math.max(x1, b.x + b.width); y1 = Math.max(y1, b.y + b.height);
    });
    var rect = svg.getBoundingClientRect();
    var aspect = rect.width / Math.max(1, rect.height);
    var w = Math.max((x1 - x0) * 2.5, (y1 - y0) * 2.5 * aspect, rect.width / 2);
    // Never wider than the view of the whole diagram, nor so close that they do not fit.
    var whole = Math.max(full.w, full.h * aspect);
    w = Math.max(Math.min(w, whole), Math.min(Math.max(x1 - x0, (y1 - y0) * aspect) * 1.05, whole));
    view = { x: (x0 + x1) / 2 - w / 2, y: (y0 + y1) / 2 - w / aspect / 2, w: w, h: w / aspect };
    apply();
  }
  function cell(row, text, header) {
    var c = document.createElement(header ? 'th' : 'td');
    c.textContent = text;
    row.appendChild(c);
  }
  function show(id) {
    var details = document.getElementById('details');
    details.textContent = '';
    var element = data.elements[id];
    if (!element) { return; }
    var title = document.createElement('p');
    title.className = 'qname';
    title.textContent = element.kind + ' ' + element.qname;
    details.appendChild(title);
    var table = document.createElement('table');
    Object.keys(element.attributes).forEach(function (name) {
      var row = document.createElement('tr');
      cell(row, name, true);
      cell(row, element.attributes[name], false);
      table.appendChild(row);
    });
    details.appendChild(table);
    var list = document.createElement('ul');
    list.className = 'element-findings';
    element.findings.forEach(function (f) {
      var item = document.createElement('li');
      item.className = f.severity;
      item.textContent = f.severity + ' ' + f.rule + ': ' + f.message;
      list.appendChild(item);
    });
    if (element.findings.length === 0) {
      var none = document.createElement('li');
      none.textContent = 'no findings';
      list.appendChild(none);
    }
    details.appendChild(list);
  }
  function select(item) {
    var items = document.querySelectorAll('#findings li, .overlay-items li');
    for (var i = 0; i < items.length; i++) { items[i].classList.remove('selected'); }
    if (item) { item.classList.add('selected'); }
  }
  function activate(item, open) {
    item.addEventListener('click', open);
    item.addEventListener('keydown', function (e) { if (e.key === 'Enter') { open(); } });
  }

  var findingItems = document.querySelectorAll('#findings li');
  for (var i = 0; i < findingItems.length; i++) {
    (function (item) {
      activate(item, function () {
        select(item);
        var target = item.getAttribute('data-target');
        var element = target ? document.getElementById(target) : null;
        highlight(element ? [element] : []);
        if (element) {
          focus([element]);
          show(target);
        }
      });
    })(findingItems[i]);
  }
  // Overlay items (a processor, a latency requirement) highlight every element they concern.
  var overlayItems = document.querySelectorAll('.overlay-items li');
  for (var j = 0; j < overlayItems.length; j++) {
    (function (item) {
      activate(item, function () {
        select(item);
        var targets = (item.getAttribute('data-targets') || '').split(' ').filter(Boolean);
        var elements = targets.map(function (id) { return document.getElementById(id); }).filter(Boolean);
        highlight(elements);
        focus(elements);
      });
    })(overlayItems[j]);
  }
  svg.addEventListener('click', function (e) {
    if (dragged) { return; }
    var element = e.target.closest('.el');
    highlight(element ? [element] : []);
    select(null);
    if (element) { show(element.id); }
  });
})();
