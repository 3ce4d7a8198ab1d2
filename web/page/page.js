// The page's JavaScript API over the WebAssembly build (web/src/page_main.cpp):
//   await pseudoshadow.ready                      -> the WebGL2 context is open
//   pseudoshadow.render(scene, overrides)         -> {width, height, rgba (Uint8Array, top row first)}
// `overrides` are --set lines ("render.size=[128,128]"); a failure throws the renderer's message.
'use strict';
var Module = {
  canvas: null,
  print: (text) => console.log(text),
  printErr: (text) => console.error(text),
};
window.pseudoshadow = (() => {
  let resolveReady, rejectReady;
  const ready = new Promise((resolve, reject) => { resolveReady = resolve; rejectReady = reject; });
  Module.onRuntimeInitialized = () => {
    if (Module.ccall('ps_web_open_gl', 'number', ['string'], ['#canvas']) !== 0) {
      rejectReady(new Error(Module.ccall('ps_web_error', 'string', [], [])));
      return;
    }
    resolveReady(Module.ccall('ps_web_gl_version', 'string', [], []));
  };
  function render(scene, overrides = []) {
    const rc = Module.ccall('ps_web_render', 'number', ['string', 'string'], [scene, overrides.join('\n')]);
    if (rc !== 0) throw new Error(Module.ccall('ps_web_error', 'string', [], []));
    const width = Module.ccall('ps_web_width', 'number', [], []);
    const height = Module.ccall('ps_web_height', 'number', [], []);
    const at = Module.ccall('ps_web_pixels', 'number', [], []);
    return { width, height, rgba: new Uint8Array(Module.HEAPU8.buffer, at, width * height * 4).slice() };
  }
  // The image on the page's own canvas (2D), for a person looking at it.
  function show(image) {
    const out = document.getElementById('out');
    out.width = image.width;
    out.height = image.height;
    out.style.width = `${image.width * 2}px`;
    const data = new ImageData(new Uint8ClampedArray(image.rgba.buffer), image.width, image.height);
    out.getContext('2d').putImageData(data, 0, 0);
  }
  window.addEventListener('DOMContentLoaded', () => {
    Module.canvas = document.getElementById('canvas');
    const status = document.getElementById('status');
    const go = () => {
      const n = Number(document.getElementById('size').value) || 256;
      try {
        const t0 = performance.now();
        show(render(document.getElementById('scene').value, [`render.size=[${n},${n}]`]));
        status.textContent = `Rendered in ${(performance.now() - t0).toFixed(0)} ms.`;
      } catch (e) {
        status.textContent = e.message;
      }
    };
    document.getElementById('go').addEventListener('click', go);
    // ?test: the browser tests call render() themselves.
    const test = new URLSearchParams(location.search).has('test');
    ready.then((version) => { status.textContent = `WebGL: ${version}.`; if (!test) go(); },
               (e) => { status.textContent = e.message; });
  });
  return { ready, render, show };
})();
