// The renderer's errors, shared by the render worker and the page (which has no three.js).

export class WebGL2UnavailableError extends Error {
  constructor() {
    super(
      'This browser or GPU provides no WebGL2 context, which drawing a shader needs. Try a current Chrome, Firefox or Safari with hardware acceleration switched on.',
    );
    this.name = 'WebGL2UnavailableError';
  }
}

export class ShaderCompileError extends Error {
  constructor(report, messages) {
    super(`Shader failed to compile:\n${report}`);
    this.name = 'ShaderCompileError';
    this.report = report;
    this.messages = messages;
  }
}
