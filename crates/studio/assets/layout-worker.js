// The layout worker: ELK (vendored elkjs) and the chart drawing of chart.js run here, off the
// page's thread, so the page draws and answers at once. Request {id, chart}; reply
// {id, svg} or {id, error}.
'use strict';
importScripts('/elk.js', '/chart.js');
// ELK's bundle takes `onmessage` when first instantiated: instantiate it before setting ours.
Chart.init();
self.onmessage = async e => {
  const {id, chart} = e.data;
  try {
    self.postMessage({id, svg: await Chart.layout(chart)});
  } catch (err) {
    self.postMessage({id, error: String(err && err.message || err)});
  }
};
