

module ept(xl,xr,px);
    
    // Module arguments
    input wire  [5:0] xl;
    input wire  [5:0] xr;
    output reg  [63:0] px;
    
    // Stub signals
    reg  root$li;
    reg  root$ri;
    reg  root$lcs;
    reg  root$rcs;
    reg  [4:0] root$xl;
    reg  [4:0] root$xr;
    wire  [63:0] root$px;
    
    // Sub module instances
    ept$root root(
        .li(root$li),
        .ri(root$ri),
        .lcs(root$lcs),
        .rcs(root$rcs),
        .xl(root$xl),
        .xr(root$xr),
        .px(root$px)
    );
    
    // Update code
    always @(*) begin
        root$li = xl[32'h5];
        root$ri = xr[32'h5];
        root$lcs = 1'b0;
        root$rcs = 1'b0;
        root$xl = xl[(32'h0)+:(5)];
        root$xr = xr[(32'h0)+:(5)];
        px = root$px;
    end
    
endmodule // ept


module ept$root(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [4:0] xl;
    input wire  [4:0] xr;
    output reg  [63:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  [3:0] left$0$xl;
    reg  [3:0] left$0$xr;
    wire  [31:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  [3:0] right$0$xl;
    reg  [3:0] right$0$xr;
    wire  [31:0] right$0$px;
    
    // Sub module instances
    ept$root$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    ept$root$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    ept$root$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h4];
        pe$xr = xr[32'h4];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(4)];
        left$0$xr = xr[(32'h0)+:(4)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(4)];
        right$0$xr = xr[(32'h0)+:(4)];
        px = ((left$0$px) & 64'hffffffffffffffff) | (((right$0$px) & 64'hffffffffffffffff) << 32'h20);
    end
    
endmodule // ept$root


module ept$root$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [3:0] xl;
    input wire  [3:0] xr;
    output reg  [31:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  [2:0] left$0$xl;
    reg  [2:0] left$0$xr;
    wire  [15:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  [2:0] right$0$xl;
    reg  [2:0] right$0$xr;
    wire  [15:0] right$0$px;
    
    // Sub module instances
    ept$root$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    ept$root$left$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    ept$root$left$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h3];
        pe$xr = xr[32'h3];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(3)];
        left$0$xr = xr[(32'h0)+:(3)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(3)];
        right$0$xr = xr[(32'h0)+:(3)];
        px = ((left$0$px) & 32'hffffffff) | (((right$0$px) & 32'hffffffff) << 32'h10);
    end
    
endmodule // ept$root$left$0


module ept$root$left$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [2:0] xl;
    input wire  [2:0] xr;
    output reg  [15:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  [1:0] left$0$xl;
    reg  [1:0] left$0$xr;
    wire  [7:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  [1:0] right$0$xl;
    reg  [1:0] right$0$xr;
    wire  [7:0] right$0$px;
    
    // Sub module instances
    ept$root$left$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    ept$root$left$0$left$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    ept$root$left$0$left$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h2];
        pe$xr = xr[32'h2];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(2)];
        left$0$xr = xr[(32'h0)+:(2)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(2)];
        right$0$xr = xr[(32'h0)+:(2)];
        px = ((left$0$px) & 16'hffff) | (((right$0$px) & 16'hffff) << 32'h8);
    end
    
endmodule // ept$root$left$0$left$0


module ept$root$left$0$left$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [1:0] xl;
    input wire  [1:0] xr;
    output reg  [7:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  left$0$xl;
    reg  left$0$xr;
    wire  [3:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  right$0$xl;
    reg  right$0$xr;
    wire  [3:0] right$0$px;
    
    // Sub module instances
    ept$root$left$0$left$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    ept$root$left$0$left$0$left$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    ept$root$left$0$left$0$left$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h1];
        pe$xr = xr[32'h1];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(1)];
        left$0$xr = xr[(32'h0)+:(1)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(1)];
        right$0$xr = xr[(32'h0)+:(1)];
        px = ((left$0$px) & 8'hff) | (((right$0$px) & 8'hff) << 32'h4);
    end
    
endmodule // ept$root$left$0$left$0$left$0


module ept$root$left$0$left$0$left$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    ept$root$left$0$left$0$left$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // ept$root$left$0$left$0$left$0$left$0


module ept$root$left$0$left$0$left$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$left$0$left$0$left$0$left$0$pe


module ept$root$left$0$left$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$left$0$left$0$left$0$pe


module ept$root$left$0$left$0$left$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    ept$root$left$0$left$0$left$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // ept$root$left$0$left$0$left$0$right$0


module ept$root$left$0$left$0$left$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$left$0$left$0$left$0$right$0$pe


module ept$root$left$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$left$0$left$0$pe


module ept$root$left$0$left$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [1:0] xl;
    input wire  [1:0] xr;
    output reg  [7:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  left$0$xl;
    reg  left$0$xr;
    wire  [3:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  right$0$xl;
    reg  right$0$xr;
    wire  [3:0] right$0$px;
    
    // Sub module instances
    ept$root$left$0$left$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    ept$root$left$0$left$0$right$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    ept$root$left$0$left$0$right$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h1];
        pe$xr = xr[32'h1];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(1)];
        left$0$xr = xr[(32'h0)+:(1)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(1)];
        right$0$xr = xr[(32'h0)+:(1)];
        px = ((left$0$px) & 8'hff) | (((right$0$px) & 8'hff) << 32'h4);
    end
    
endmodule // ept$root$left$0$left$0$right$0


module ept$root$left$0$left$0$right$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    ept$root$left$0$left$0$right$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // ept$root$left$0$left$0$right$0$left$0


module ept$root$left$0$left$0$right$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$left$0$left$0$right$0$left$0$pe


module ept$root$left$0$left$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$left$0$left$0$right$0$pe


module ept$root$left$0$left$0$right$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    ept$root$left$0$left$0$right$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // ept$root$left$0$left$0$right$0$right$0


module ept$root$left$0$left$0$right$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$left$0$left$0$right$0$right$0$pe


module ept$root$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$left$0$pe


module ept$root$left$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [2:0] xl;
    input wire  [2:0] xr;
    output reg  [15:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  [1:0] left$0$xl;
    reg  [1:0] left$0$xr;
    wire  [7:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  [1:0] right$0$xl;
    reg  [1:0] right$0$xr;
    wire  [7:0] right$0$px;
    
    // Sub module instances
    ept$root$left$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    ept$root$left$0$right$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    ept$root$left$0$right$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h2];
        pe$xr = xr[32'h2];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(2)];
        left$0$xr = xr[(32'h0)+:(2)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(2)];
        right$0$xr = xr[(32'h0)+:(2)];
        px = ((left$0$px) & 16'hffff) | (((right$0$px) & 16'hffff) << 32'h8);
    end
    
endmodule // ept$root$left$0$right$0


module ept$root$left$0$right$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [1:0] xl;
    input wire  [1:0] xr;
    output reg  [7:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  left$0$xl;
    reg  left$0$xr;
    wire  [3:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  right$0$xl;
    reg  right$0$xr;
    wire  [3:0] right$0$px;
    
    // Sub module instances
    ept$root$left$0$right$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    ept$root$left$0$right$0$left$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    ept$root$left$0$right$0$left$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h1];
        pe$xr = xr[32'h1];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(1)];
        left$0$xr = xr[(32'h0)+:(1)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(1)];
        right$0$xr = xr[(32'h0)+:(1)];
        px = ((left$0$px) & 8'hff) | (((right$0$px) & 8'hff) << 32'h4);
    end
    
endmodule // ept$root$left$0$right$0$left$0


module ept$root$left$0$right$0$left$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    ept$root$left$0$right$0$left$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // ept$root$left$0$right$0$left$0$left$0


module ept$root$left$0$right$0$left$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$left$0$right$0$left$0$left$0$pe


module ept$root$left$0$right$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$left$0$right$0$left$0$pe


module ept$root$left$0$right$0$left$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    ept$root$left$0$right$0$left$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // ept$root$left$0$right$0$left$0$right$0


module ept$root$left$0$right$0$left$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$left$0$right$0$left$0$right$0$pe


module ept$root$left$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$left$0$right$0$pe


module ept$root$left$0$right$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [1:0] xl;
    input wire  [1:0] xr;
    output reg  [7:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  left$0$xl;
    reg  left$0$xr;
    wire  [3:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  right$0$xl;
    reg  right$0$xr;
    wire  [3:0] right$0$px;
    
    // Sub module instances
    ept$root$left$0$right$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    ept$root$left$0$right$0$right$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    ept$root$left$0$right$0$right$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h1];
        pe$xr = xr[32'h1];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(1)];
        left$0$xr = xr[(32'h0)+:(1)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(1)];
        right$0$xr = xr[(32'h0)+:(1)];
        px = ((left$0$px) & 8'hff) | (((right$0$px) & 8'hff) << 32'h4);
    end
    
endmodule // ept$root$left$0$right$0$right$0


module ept$root$left$0$right$0$right$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    ept$root$left$0$right$0$right$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // ept$root$left$0$right$0$right$0$left$0


module ept$root$left$0$right$0$right$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$left$0$right$0$right$0$left$0$pe


module ept$root$left$0$right$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$left$0$right$0$right$0$pe


module ept$root$left$0$right$0$right$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    ept$root$left$0$right$0$right$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // ept$root$left$0$right$0$right$0$right$0


module ept$root$left$0$right$0$right$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$left$0$right$0$right$0$right$0$pe


module ept$root$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$pe


module ept$root$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [3:0] xl;
    input wire  [3:0] xr;
    output reg  [31:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  [2:0] left$0$xl;
    reg  [2:0] left$0$xr;
    wire  [15:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  [2:0] right$0$xl;
    reg  [2:0] right$0$xr;
    wire  [15:0] right$0$px;
    
    // Sub module instances
    ept$root$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    ept$root$right$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    ept$root$right$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h3];
        pe$xr = xr[32'h3];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(3)];
        left$0$xr = xr[(32'h0)+:(3)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(3)];
        right$0$xr = xr[(32'h0)+:(3)];
        px = ((left$0$px) & 32'hffffffff) | (((right$0$px) & 32'hffffffff) << 32'h10);
    end
    
endmodule // ept$root$right$0


module ept$root$right$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [2:0] xl;
    input wire  [2:0] xr;
    output reg  [15:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  [1:0] left$0$xl;
    reg  [1:0] left$0$xr;
    wire  [7:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  [1:0] right$0$xl;
    reg  [1:0] right$0$xr;
    wire  [7:0] right$0$px;
    
    // Sub module instances
    ept$root$right$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    ept$root$right$0$left$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    ept$root$right$0$left$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h2];
        pe$xr = xr[32'h2];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(2)];
        left$0$xr = xr[(32'h0)+:(2)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(2)];
        right$0$xr = xr[(32'h0)+:(2)];
        px = ((left$0$px) & 16'hffff) | (((right$0$px) & 16'hffff) << 32'h8);
    end
    
endmodule // ept$root$right$0$left$0


module ept$root$right$0$left$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [1:0] xl;
    input wire  [1:0] xr;
    output reg  [7:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  left$0$xl;
    reg  left$0$xr;
    wire  [3:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  right$0$xl;
    reg  right$0$xr;
    wire  [3:0] right$0$px;
    
    // Sub module instances
    ept$root$right$0$left$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    ept$root$right$0$left$0$left$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    ept$root$right$0$left$0$left$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h1];
        pe$xr = xr[32'h1];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(1)];
        left$0$xr = xr[(32'h0)+:(1)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(1)];
        right$0$xr = xr[(32'h0)+:(1)];
        px = ((left$0$px) & 8'hff) | (((right$0$px) & 8'hff) << 32'h4);
    end
    
endmodule // ept$root$right$0$left$0$left$0


module ept$root$right$0$left$0$left$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    ept$root$right$0$left$0$left$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // ept$root$right$0$left$0$left$0$left$0


module ept$root$right$0$left$0$left$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$right$0$left$0$left$0$left$0$pe


module ept$root$right$0$left$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$right$0$left$0$left$0$pe


module ept$root$right$0$left$0$left$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    ept$root$right$0$left$0$left$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // ept$root$right$0$left$0$left$0$right$0


module ept$root$right$0$left$0$left$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$right$0$left$0$left$0$right$0$pe


module ept$root$right$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$right$0$left$0$pe


module ept$root$right$0$left$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [1:0] xl;
    input wire  [1:0] xr;
    output reg  [7:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  left$0$xl;
    reg  left$0$xr;
    wire  [3:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  right$0$xl;
    reg  right$0$xr;
    wire  [3:0] right$0$px;
    
    // Sub module instances
    ept$root$right$0$left$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    ept$root$right$0$left$0$right$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    ept$root$right$0$left$0$right$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h1];
        pe$xr = xr[32'h1];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(1)];
        left$0$xr = xr[(32'h0)+:(1)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(1)];
        right$0$xr = xr[(32'h0)+:(1)];
        px = ((left$0$px) & 8'hff) | (((right$0$px) & 8'hff) << 32'h4);
    end
    
endmodule // ept$root$right$0$left$0$right$0


module ept$root$right$0$left$0$right$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    ept$root$right$0$left$0$right$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // ept$root$right$0$left$0$right$0$left$0


module ept$root$right$0$left$0$right$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$right$0$left$0$right$0$left$0$pe


module ept$root$right$0$left$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$right$0$left$0$right$0$pe


module ept$root$right$0$left$0$right$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    ept$root$right$0$left$0$right$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // ept$root$right$0$left$0$right$0$right$0


module ept$root$right$0$left$0$right$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$right$0$left$0$right$0$right$0$pe


module ept$root$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$right$0$pe


module ept$root$right$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [2:0] xl;
    input wire  [2:0] xr;
    output reg  [15:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  [1:0] left$0$xl;
    reg  [1:0] left$0$xr;
    wire  [7:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  [1:0] right$0$xl;
    reg  [1:0] right$0$xr;
    wire  [7:0] right$0$px;
    
    // Sub module instances
    ept$root$right$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    ept$root$right$0$right$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    ept$root$right$0$right$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h2];
        pe$xr = xr[32'h2];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(2)];
        left$0$xr = xr[(32'h0)+:(2)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(2)];
        right$0$xr = xr[(32'h0)+:(2)];
        px = ((left$0$px) & 16'hffff) | (((right$0$px) & 16'hffff) << 32'h8);
    end
    
endmodule // ept$root$right$0$right$0


module ept$root$right$0$right$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [1:0] xl;
    input wire  [1:0] xr;
    output reg  [7:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  left$0$xl;
    reg  left$0$xr;
    wire  [3:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  right$0$xl;
    reg  right$0$xr;
    wire  [3:0] right$0$px;
    
    // Sub module instances
    ept$root$right$0$right$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    ept$root$right$0$right$0$left$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    ept$root$right$0$right$0$left$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h1];
        pe$xr = xr[32'h1];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(1)];
        left$0$xr = xr[(32'h0)+:(1)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(1)];
        right$0$xr = xr[(32'h0)+:(1)];
        px = ((left$0$px) & 8'hff) | (((right$0$px) & 8'hff) << 32'h4);
    end
    
endmodule // ept$root$right$0$right$0$left$0


module ept$root$right$0$right$0$left$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    ept$root$right$0$right$0$left$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // ept$root$right$0$right$0$left$0$left$0


module ept$root$right$0$right$0$left$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$right$0$right$0$left$0$left$0$pe


module ept$root$right$0$right$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$right$0$right$0$left$0$pe


module ept$root$right$0$right$0$left$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    ept$root$right$0$right$0$left$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // ept$root$right$0$right$0$left$0$right$0


module ept$root$right$0$right$0$left$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$right$0$right$0$left$0$right$0$pe


module ept$root$right$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$right$0$right$0$pe


module ept$root$right$0$right$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [1:0] xl;
    input wire  [1:0] xr;
    output reg  [7:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  left$0$xl;
    reg  left$0$xr;
    wire  [3:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  right$0$xl;
    reg  right$0$xr;
    wire  [3:0] right$0$px;
    
    // Sub module instances
    ept$root$right$0$right$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    ept$root$right$0$right$0$right$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    ept$root$right$0$right$0$right$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h1];
        pe$xr = xr[32'h1];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(1)];
        left$0$xr = xr[(32'h0)+:(1)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(1)];
        right$0$xr = xr[(32'h0)+:(1)];
        px = ((left$0$px) & 8'hff) | (((right$0$px) & 8'hff) << 32'h4);
    end
    
endmodule // ept$root$right$0$right$0$right$0


module ept$root$right$0$right$0$right$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    ept$root$right$0$right$0$right$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // ept$root$right$0$right$0$right$0$left$0


module ept$root$right$0$right$0$right$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$right$0$right$0$right$0$left$0$pe


module ept$root$right$0$right$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$right$0$right$0$right$0$pe


module ept$root$right$0$right$0$right$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    ept$root$right$0$right$0$right$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // ept$root$right$0$right$0$right$0$right$0


module ept$root$right$0$right$0$right$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // ept$root$right$0$right$0$right$0$right$0$pe
